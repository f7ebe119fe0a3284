// A column of PLY values held in the property's own type (uchar colours as bytes, int ids as
// ints, float positions as floats), so a read/write round trip keeps each value and its type.
// Values go in and out as double, which every PLY scalar type converts to exactly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <variant>
#include <vector>

namespace qd::io {

// In the order of ScalarColumn's alternatives.
enum class ScalarType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

// PLY name ("uchar", "float", ...) of a type, and its size in bytes.
const char* scalar_type_name(ScalarType type);
std::size_t scalar_type_size(ScalarType type);

class ScalarColumn {
 public:
  explicit ScalarColumn(ScalarType type = ScalarType::Float32);
  // Throws qd::common::Error when a value does not fit `type` (scalar_value.h).
  ScalarColumn(ScalarType type, const std::vector<double>& values);

  ScalarType type() const { return static_cast<ScalarType>(data_.index()); }
  std::size_t size() const;
  double operator[](std::size_t i) const;
  // Throws qd::common::Error when the value does not fit the column's type.
  void push_back(double value);
  void reserve(std::size_t n);
  std::vector<double> to_doubles() const;

  bool operator==(const ScalarColumn& other) const { return data_ == other.data_; }

 private:
  std::variant<std::vector<std::int8_t>, std::vector<std::uint8_t>, std::vector<std::int16_t>,
               std::vector<std::uint16_t>, std::vector<std::int32_t>, std::vector<std::uint32_t>,
               std::vector<float>, std::vector<double>>
      data_;
};

}  // namespace qd::io
