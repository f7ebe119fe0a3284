#include "io/scalar_column.h"

#include <string>

#include "common/error.h"
#include "io/scalar_value.h"

namespace qd::io {

namespace {

[[noreturn]] void throw_misfit(double value, ScalarType type) {
  throw common::Error("value " + std::to_string(value) + " does not fit type " +
                      scalar_type_name(type));
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
  return with_scalar_type(type, [](auto value) { return sizeof value; });
}

ScalarColumn::ScalarColumn(ScalarType type) {
  with_scalar_type(type, [this](auto value) { data_.emplace<std::vector<decltype(value)>>(); });
}

ScalarColumn::ScalarColumn(ScalarType type, const std::vector<double>& values)
    : ScalarColumn(type) {
  visit([&values, type](auto& column) {
    using T = typename std::decay_t<decltype(column)>::value_type;
    column.reserve(values.size());
    for (double v : values) {
      if (!fits_type<T>(v)) throw_misfit(v, type);
      column.push_back(static_cast<T>(v));
    }
  });
}

std::size_t ScalarColumn::size() const {
  return std::visit([](const auto& v) { return v.size(); }, data_);
}

double ScalarColumn::operator[](std::size_t i) const {
  return std::visit([i](const auto& v) { return static_cast<double>(v[i]); }, data_);
}

void ScalarColumn::push_back(double value) {
  if (!fits_scalar_type(type(), value)) throw_misfit(value, type());
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
