// Checks that a value can be stored in a PLY scalar type without change.
#pragma once

#include "io/scalar_column.h"

namespace qd::io {

// True when `value` is representable in `type`: integer types need an integral value within
// their range; float accepts any value whose magnitude fits (or a non-finite one); double any.
bool fits_scalar_type(ScalarType type, double value);

}  // namespace qd::io
