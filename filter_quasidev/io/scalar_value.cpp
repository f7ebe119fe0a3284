#include "io/scalar_value.h"

namespace qd::io {

bool fits_scalar_type(ScalarType type, double value) {
  return with_scalar_type(type, [value](auto t) { return fits_type<decltype(t)>(value); });
}

}  // namespace qd::io
