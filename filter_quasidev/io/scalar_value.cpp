#include "io/scalar_value.h"

#include <cmath>
#include <limits>

namespace qd::io {

namespace {

template <typename T>
bool fits_integer(double value) {
  return std::isfinite(value) && std::trunc(value) == value &&
         value >= static_cast<double>(std::numeric_limits<T>::min()) &&
         value <= static_cast<double>(std::numeric_limits<T>::max());
}

}  // namespace

bool fits_scalar_type(ScalarType type, double value) {
  switch (type) {
    case ScalarType::Int8:
      return fits_integer<signed char>(value);
    case ScalarType::UInt8:
      return fits_integer<unsigned char>(value);
    case ScalarType::Int16:
      return fits_integer<short>(value);
    case ScalarType::UInt16:
      return fits_integer<unsigned short>(value);
    case ScalarType::Int32:
      return fits_integer<int>(value);
    case ScalarType::UInt32:
      return fits_integer<unsigned int>(value);
    case ScalarType::Float32:
      return !std::isfinite(value) ||
             std::fabs(value) <= static_cast<double>(std::numeric_limits<float>::max());
    case ScalarType::Float64:
      return true;
  }
  return false;
}

}  // namespace qd::io
