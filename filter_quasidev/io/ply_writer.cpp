#include "io/ply_writer.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <type_traits>

#include "common/error.h"
#include "io/scalar_value.h"

namespace qd::io {

namespace {

const char* format_name(PlyFormat format) {
  switch (format) {
    case PlyFormat::Ascii:
      return "ascii";
    case PlyFormat::BinaryLittleEndian:
      return "binary_little_endian";
    case PlyFormat::BinaryBigEndian:
      return "binary_big_endian";
  }
  return "?";
}

std::string header(const PlyTables& ply, PlyFormat format) {
  std::string h = "ply\nformat " + std::string(format_name(format)) + " 1.0\n";
  for (const std::string& c : ply.comments) h += "comment " + c + "\n";
  for (const std::string& c : ply.obj_info) h += "obj_info " + c + "\n";
  for (const PlyElement& e : ply.elements) {
    h += "element " + e.name + " " + std::to_string(e.count) + "\n";
    for (const PlyProperty& p : e.properties) {
      h += "property ";
      if (p.is_list) h += std::string("list ") + scalar_type_name(p.count_type) + " ";
      h += std::string(scalar_type_name(p.type())) + " " + p.name + "\n";
    }
  }
  return h + "end_header\n";
}

template <typename T>
void append_raw(T v, bool big_endian, std::string& out) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &v, sizeof v);
  if (big_endian)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
  out.append(reinterpret_cast<const char*>(raw), sizeof raw);
}

// Shortest text that reads back to the same value of T.
template <typename T>
void append_text(T v, std::string& out) {
  char buffer[40];  // not format_text: a stack buffer for every value of every PLY written
  if constexpr (std::is_same_v<T, float>)
    std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(v));
  else if constexpr (std::is_same_v<T, double>)
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
  else
    std::snprintf(buffer, sizeof buffer, "%lld", static_cast<long long>(v));
  out += buffer;
}

template <typename T>
void append_value(T v, PlyFormat format, std::string& out) {
  if (format == PlyFormat::Ascii) {
    append_text(v, out);
    out += ' ';
  } else {
    append_raw(v, format == PlyFormat::BinaryBigEndian, out);
  }
}

// Appends the list length of item i of list property p, in p's count type.
void append_list_length(const PlyElement& e, const PlyProperty& p, std::size_t i, PlyFormat format,
                        std::string& out) {
  const std::size_t n = p.list_size(i);
  with_scalar_type(p.count_type, [&](auto count) {
    using Count = decltype(count);
    if (!fits_type<Count>(static_cast<double>(n)))
      throw common::Error("cannot write property '" + p.name + "' of " + e.name + " " +
                          std::to_string(i) + ": list length " + std::to_string(n) +
                          " does not fit type " + scalar_type_name(p.count_type));
    append_value(static_cast<Count>(n), format, out);
  });
}

// Appends item i's entry of property p (a value, or a list) from `column`, p's typed values.
template <typename T>
void append_entry(const PlyElement& e, const PlyProperty& p, std::size_t i,
                  const std::vector<T>& column, PlyFormat format, std::string& out) {
  if (!p.is_list) {
    append_value(column[i], format, out);
    return;
  }
  append_list_length(e, p, i, format, out);
  for (std::size_t k = p.offsets[i]; k < p.offsets[i + 1]; ++k)
    append_value(column[k], format, out);
}

void append_element(const PlyElement& e, PlyFormat format, std::string& out) {
  for (const PlyProperty& p : e.properties) {
    const std::size_t expected = p.is_list ? e.count + 1 : e.count;
    if ((p.is_list ? p.offsets.size() : p.values.size()) != expected)
      throw common::Error("internal error: property '" + p.name + "' of element '" + e.name +
                          "' does not have one entry per element");
  }
  for (std::size_t i = 0; i < e.count; ++i) {
    for (const PlyProperty& p : e.properties)
      p.values.visit([&](const auto& column) { append_entry(e, p, i, column, format, out); });
    if (format == PlyFormat::Ascii && !e.properties.empty()) out.back() = '\n';
  }
}

}  // namespace

std::string serialize_ply_tables(const PlyTables& ply, PlyFormat format) {
  std::string out = header(ply, format);
  for (const PlyElement& e : ply.elements) append_element(e, format, out);
  return out;
}

}  // namespace qd::io
