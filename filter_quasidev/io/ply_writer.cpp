#include "io/ply_writer.h"

#include <cstdint>
#include <cstdio>
#include <cstring>

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

void append_binary(ScalarType type, double v, bool big_endian, std::string& out) {
  switch (type) {
    case ScalarType::Int8:
      return append_raw(static_cast<std::int8_t>(v), big_endian, out);
    case ScalarType::UInt8:
      return append_raw(static_cast<std::uint8_t>(v), big_endian, out);
    case ScalarType::Int16:
      return append_raw(static_cast<std::int16_t>(v), big_endian, out);
    case ScalarType::UInt16:
      return append_raw(static_cast<std::uint16_t>(v), big_endian, out);
    case ScalarType::Int32:
      return append_raw(static_cast<std::int32_t>(v), big_endian, out);
    case ScalarType::UInt32:
      return append_raw(static_cast<std::uint32_t>(v), big_endian, out);
    case ScalarType::Float32:
      return append_raw(static_cast<float>(v), big_endian, out);
    case ScalarType::Float64:
      return append_raw(v, big_endian, out);
  }
}

// Shortest text that reads back to the same value of the type.
void append_text(ScalarType type, double v, std::string& out) {
  char buffer[40];  // not format_text: a stack buffer for every value of every PLY written
  if (type == ScalarType::Float32)
    std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(static_cast<float>(v)));
  else if (type == ScalarType::Float64)
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
  else
    std::snprintf(buffer, sizeof buffer, "%lld", static_cast<long long>(v));
  out += buffer;
}

// Appends value v of property p of element e's item i (named in the error, built only then).
void append_value(ScalarType type, double v, PlyFormat format, const PlyElement& e,
                  const PlyProperty& p, std::size_t i, std::string& out) {
  if (!fits_scalar_type(type, v))
    throw common::Error("cannot write property '" + p.name + "' of " + e.name + " " +
                        std::to_string(i) + ": value " + std::to_string(v) + " does not fit type " +
                        scalar_type_name(type));
  if (format == PlyFormat::Ascii) {
    append_text(type, v, out);
    out += ' ';
  } else {
    append_binary(type, v, format == PlyFormat::BinaryBigEndian, out);
  }
}

void append_element(const PlyElement& e, PlyFormat format, std::string& out) {
  for (const PlyProperty& p : e.properties) {
    const std::size_t expected = p.is_list ? e.count + 1 : e.count;
    if ((p.is_list ? p.offsets.size() : p.values.size()) != expected)
      throw common::Error("internal error: property '" + p.name + "' of element '" + e.name +
                          "' does not have one entry per element");
  }
  for (std::size_t i = 0; i < e.count; ++i) {
    for (const PlyProperty& p : e.properties) {
      if (!p.is_list) {
        append_value(p.type(), p.values[i], format, e, p, i, out);
        continue;
      }
      append_value(p.count_type, static_cast<double>(p.list_size(i)), format, e, p, i, out);
      for (std::size_t k = p.offsets[i]; k < p.offsets[i + 1]; ++k)
        append_value(p.type(), p.values[k], format, e, p, i, out);
    }
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
