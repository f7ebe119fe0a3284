// Checks that a value can be stored in a PLY scalar type without change.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "io/scalar_column.h"

namespace qd::io {

// True when `value` is representable as T: integer types need an integral value within their
// range; float accepts any value whose magnitude fits (or a non-finite one); double any.
template <typename T>
bool fits_type(double value) {
  if constexpr (std::is_integral_v<T>)
    return std::isfinite(value) && std::trunc(value) == value &&
           value >= static_cast<double>(std::numeric_limits<T>::min()) &&
           value <= static_cast<double>(std::numeric_limits<T>::max());
  else if constexpr (std::is_same_v<T, float>)
    return !std::isfinite(value) ||
           std::fabs(value) <= static_cast<double>(std::numeric_limits<float>::max());
  else
    return true;
}

// fits_type for the C++ type of `type`.
bool fits_scalar_type(ScalarType type, double value);

}  // namespace qd::io
