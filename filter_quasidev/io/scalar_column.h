// A column of PLY values held in the property's own type (uchar colours as bytes, int ids as
// ints, float positions as floats), so a read/write round trip keeps each value and its type.
// Bulk work visits the typed vector once (visit); single values go in and out as double, which
// every PLY scalar type converts to exactly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace qd::io {

// In the order of ScalarColumn's alternatives.
enum class ScalarType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

// PLY name ("uchar", "float", ...) of a type, and its size in bytes.
const char* scalar_type_name(ScalarType type);
std::size_t scalar_type_size(ScalarType type);

// Calls f(T()) with T the C++ type of `type` (std::uint8_t for UInt8, float for Float32, ...).
template <typename F>
decltype(auto) with_scalar_type(ScalarType type, F&& f) {
  switch (type) {
    case ScalarType::Int8:
      return f(std::int8_t());
    case ScalarType::UInt8:
      return f(std::uint8_t());
    case ScalarType::Int16:
      return f(std::int16_t());
    case ScalarType::UInt16:
      return f(std::uint16_t());
    case ScalarType::Int32:
      return f(std::int32_t());
    case ScalarType::UInt32:
      return f(std::uint32_t());
    case ScalarType::Float32:
      return f(float());
    case ScalarType::Float64:
      break;
  }
  return f(double());
}

// The ScalarType of the C++ type T (UInt8 for std::uint8_t, Float32 for float, ...).
template <typename T>
constexpr ScalarType scalar_type_of() {
  if constexpr (std::is_same_v<T, std::int8_t>) return ScalarType::Int8;
  if constexpr (std::is_same_v<T, std::uint8_t>) return ScalarType::UInt8;
  if constexpr (std::is_same_v<T, std::int16_t>) return ScalarType::Int16;
  if constexpr (std::is_same_v<T, std::uint16_t>) return ScalarType::UInt16;
  if constexpr (std::is_same_v<T, std::int32_t>) return ScalarType::Int32;
  if constexpr (std::is_same_v<T, std::uint32_t>) return ScalarType::UInt32;
  if constexpr (std::is_same_v<T, float>) return ScalarType::Float32;
  return ScalarType::Float64;
}

class ScalarColumn {
 public:
  explicit ScalarColumn(ScalarType type = ScalarType::Float32);
  // Throws qd::common::Error when a value does not fit `type` (scalar_value.h).
  ScalarColumn(ScalarType type, const std::vector<double>& values);
  // The column of T's PLY type holding `values`.
  template <typename T>
  explicit ScalarColumn(std::vector<T> values) : data_(std::move(values)) {}

  ScalarType type() const { return static_cast<ScalarType>(data_.index()); }
  std::size_t size() const;
  double operator[](std::size_t i) const;
  // Throws qd::common::Error when the value does not fit the column's type.
  void push_back(double value);
  void reserve(std::size_t n);
  std::vector<double> to_doubles() const;
  // Calls f with the typed vector (std::vector<std::uint8_t>&, std::vector<float>&, ...).
  template <typename F>
  decltype(auto) visit(F&& f) {
    return std::visit(std::forward<F>(f), data_);
  }
  template <typename F>
  decltype(auto) visit(F&& f) const {
    return std::visit(std::forward<F>(f), data_);
  }

  bool operator==(const ScalarColumn& other) const { return data_ == other.data_; }

 private:
  std::variant<std::vector<std::int8_t>, std::vector<std::uint8_t>, std::vector<std::int16_t>,
               std::vector<std::uint16_t>, std::vector<std::int32_t>, std::vector<std::uint32_t>,
               std::vector<float>, std::vector<double>>
      data_;
};

}  // namespace qd::io
