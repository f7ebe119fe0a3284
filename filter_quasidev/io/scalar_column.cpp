#include "io/scalar_column.h"

#include <string>

#include "common/error.h"
#include "io/scalar_value.h"

namespace qd::io {

namespace {

// The variant alternative of `type`, holding an empty vector.
template <std::size_t I = 0, typename Variant>
void select_type(Variant& data, ScalarType type) {
  if constexpr (I < std::variant_size_v<Variant>) {
    if (static_cast<std::size_t>(type) == I)
      data.template emplace<I>();
    else
      select_type<I + 1>(data, type);
  }
}

}  // namespace

const char* scalar_type_name(ScalarType type) {
  switch (type) {
    case ScalarType::Int8:
      return "char";
    case ScalarType::UInt8:
      return "uchar";
    case ScalarType::Int16:
      return "short";
    case ScalarType::UInt16:
      return "ushort";
    case ScalarType::Int32:
      return "int";
    case ScalarType::UInt32:
      return "uint";
    case ScalarType::Float32:
      return "float";
    case ScalarType::Float64:
      return "double";
  }
  return "?";
}

std::size_t scalar_type_size(ScalarType type) {
  switch (type) {
    case ScalarType::Int8:
    case ScalarType::UInt8:
      return 1;
    case ScalarType::Int16:
    case ScalarType::UInt16:
      return 2;
    case ScalarType::Int32:
    case ScalarType::UInt32:
    case ScalarType::Float32:
      return 4;
    case ScalarType::Float64:
      return 8;
  }
  return 0;
}

ScalarColumn::ScalarColumn(ScalarType type) { select_type(data_, type); }

ScalarColumn::ScalarColumn(ScalarType type, const std::vector<double>& values)
    : ScalarColumn(type) {
  reserve(values.size());
  for (double v : values) push_back(v);
}

std::size_t ScalarColumn::size() const {
  return std::visit([](const auto& v) { return v.size(); }, data_);
}

double ScalarColumn::operator[](std::size_t i) const {
  return std::visit([i](const auto& v) { return static_cast<double>(v[i]); }, data_);
}

void ScalarColumn::push_back(double value) {
  if (!fits_scalar_type(type(), value))
    throw common::Error("value " + std::to_string(value) + " does not fit type " +
                        scalar_type_name(type()));
  std::visit(
      [value](auto& v) {
        v.push_back(static_cast<typename std::decay_t<decltype(v)>::value_type>(value));
      },
      data_);
}

void ScalarColumn::reserve(std::size_t n) {
  std::visit([n](auto& v) { v.reserve(n); }, data_);
}

std::vector<double> ScalarColumn::to_doubles() const {
  return std::visit([](const auto& v) { return std::vector<double>(v.begin(), v.end()); }, data_);
}

}  // namespace qd::io
