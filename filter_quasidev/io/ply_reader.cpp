// Ours, not vcglib's PLY importer (wrap/ply/plylib + import_ply), on purpose: the command must
// hand back every property and element of the input bit-identical (any scalar type, any list,
// elements it does not know), while vcglib's reads only what maps onto a mesh type, converting
// types on the way; and a malformed, truncated or hostile file must give one clear error, never
// an abort, while plylib checks much of its input with assert (162 in plylib.cpp). Fuzzed with
// the other readers (tests/cli/fuzz).
#include "io/ply_reader.h"

#include <charconv>
#include <cstdint>
#include <cstring>
#include <utility>

#include "common/error.h"
#include "io/scalar_value.h"
#include "io/text_scan.h"

namespace qd::io {

namespace {

[[noreturn]] void fail(const std::string& message) { throw common::Error("PLY: " + message); }

bool parse_type(std::string_view word, ScalarType& type) {
  static const std::pair<const char*, ScalarType> names[] = {
      {"char", ScalarType::Int8},      {"int8", ScalarType::Int8},
      {"uchar", ScalarType::UInt8},    {"uint8", ScalarType::UInt8},
      {"short", ScalarType::Int16},    {"int16", ScalarType::Int16},
      {"ushort", ScalarType::UInt16},  {"uint16", ScalarType::UInt16},
      {"int", ScalarType::Int32},      {"int32", ScalarType::Int32},
      {"uint", ScalarType::UInt32},    {"uint32", ScalarType::UInt32},
      {"float", ScalarType::Float32},  {"float32", ScalarType::Float32},
      {"double", ScalarType::Float64}, {"float64", ScalarType::Float64}};
  for (const auto& [name, t] : names)
    if (word == name) {
      type = t;
      return true;
    }
  return false;
}

std::string rest_of_line(std::string_view line, std::string_view keyword) {
  std::string_view rest = line.substr(line.find(keyword) + keyword.size());
  if (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
  return std::string(rest);
}

void parse_property_line(const std::vector<std::string_view>& w, int line_no, PlyTables& ply) {
  const std::string at = "header line " + std::to_string(line_no) + ": ";
  if (ply.elements.empty()) fail(at + "property before any element");
  PlyProperty p;
  const bool list = w.size() >= 2 && w[1] == "list";
  if (list ? w.size() != 5 : w.size() != 3)
    fail(at + "expected 'property TYPE NAME' or 'property list COUNTTYPE TYPE NAME'");
  p.is_list = list;
  if (list && !parse_type(w[2], p.count_type))
    fail(at + "unknown list count type '" + std::string(w[2]) + "'");
  if (list && (p.count_type == ScalarType::Float32 || p.count_type == ScalarType::Float64))
    fail(at + "a list count type must be an integer type, not '" + std::string(w[2]) + "'");
  const std::string_view type_word = w[list ? 3 : 1];
  ScalarType type = ScalarType::Float32;
  if (!parse_type(type_word, type))
    fail(at + "unknown property type '" + std::string(type_word) + "'");
  p.values = ScalarColumn(type);
  p.name = std::string(w.back());
  PlyElement& element = ply.elements.back();
  if (element.find(p.name) >= 0)
    fail(at + "property '" + p.name + "' appears twice in element '" + element.name + "'");
  element.properties.push_back(std::move(p));
}

void parse_element_line(const std::vector<std::string_view>& w, int line_no, PlyTables& ply) {
  const std::string at = "header line " + std::to_string(line_no) + ": ";
  if (w.size() != 3) fail(at + "expected 'element NAME COUNT'");
  std::uint64_t count = 0;
  const auto [end, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), count);
  if (ec != std::errc() || end != w[2].data() + w[2].size())
    fail(at + "element count '" + std::string(w[2]) + "' is not a non-negative integer");
  if (ply.find(std::string(w[1]))) fail(at + "element '" + std::string(w[1]) + "' appears twice");
  PlyElement e;
  e.name = std::string(w[1]);
  e.count = static_cast<std::size_t>(count);
  ply.elements.push_back(std::move(e));
}

// Reads the header; returns the offset of the first data byte.
std::size_t parse_header(std::string_view bytes, PlyTables& ply) {
  std::size_t pos = 0;
  std::string_view line;
  if (!next_line(bytes, pos, line) || line != "ply")
    fail("the file does not start with 'ply' (not a PLY file, or empty)");
  int line_no = 1;
  bool have_format = false;
  while (next_line(bytes, pos, line)) {
    ++line_no;
    const std::vector<std::string_view> w = split_words(line);
    if (w.empty()) continue;
    const std::string at = "header line " + std::to_string(line_no) + ": ";
    if (w[0] == "end_header") {
      if (!have_format) fail(at + "end_header before the format line");
      return pos;
    } else if (w[0] == "comment") {
      ply.comments.push_back(rest_of_line(line, "comment"));
    } else if (w[0] == "obj_info") {
      ply.obj_info.push_back(rest_of_line(line, "obj_info"));
    } else if (w[0] == "format") {
      if (w.size() != 3 || w[2] != "1.0") fail(at + "expected 'format KIND 1.0'");
      if (w[1] == "ascii")
        ply.format = PlyFormat::Ascii;
      else if (w[1] == "binary_little_endian")
        ply.format = PlyFormat::BinaryLittleEndian;
      else if (w[1] == "binary_big_endian")
        ply.format = PlyFormat::BinaryBigEndian;
      else
        fail(at + "unknown format '" + std::string(w[1]) + "'");
      have_format = true;
    } else if (w[0] == "element") {
      parse_element_line(w, line_no, ply);
    } else if (w[0] == "property") {
      parse_property_line(w, line_no, ply);
    } else {
      fail(at + "unknown keyword '" + std::string(w[0]) + "'");
    }
  }
  fail("the header is not terminated by 'end_header' (file truncated?)");
}

// Where a value is read from: formatted only when a message needs it.
struct Place {
  const PlyElement& element;
  std::size_t index;
  const PlyProperty& property;
  bool list_length;

  std::string text() const {
    return std::string(list_length ? "list length of " : "") + "property '" + property.name +
           "' of " + element.name + " " + std::to_string(index) + " (of " +
           std::to_string(element.count) + ")";
  }
};

// Data source for ascii files: whitespace-separated tokens, line numbers for messages.
class AsciiSource {
 public:
  AsciiSource(std::string_view bytes, std::size_t pos, int line)
      : bytes_(bytes), pos_(pos), line_(line) {}

  // Each value takes at least one character.
  std::size_t min_bytes(ScalarType) const { return 1; }
  std::size_t remaining() const { return bytes_.size() - pos_; }

  template <typename T>
  T read(const Place& place) {
    const std::string_view token = next_token(place);
    double value = 0;
    if (!parse_number(token, value) || !fits_type<T>(value))
      fail("line " + std::to_string(line_) + ": '" + std::string(token.substr(0, 40)) +
           "' is not a valid " + scalar_type_name(scalar_type_of<T>()) + " for " + place.text());
    // A float property holds the nearest float, as a binary file would.
    return static_cast<T>(value);
  }

  void expect_end() {
    skip_space();
    if (pos_ < bytes_.size())
      fail("line " + std::to_string(line_) +
           ": unexpected data after the last element (do the header's element counts match the "
           "data?)");
  }

 private:
  void skip_space() {
    while (pos_ < bytes_.size() && is_space(bytes_[pos_])) {
      if (bytes_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }

  std::string_view next_token(const Place& place) {
    skip_space();
    if (pos_ >= bytes_.size())
      fail("the data ends early (line " + std::to_string(line_) + "): missing " + place.text() +
           " (wrong element counts or truncated file)");
    const std::size_t start = pos_;
    while (pos_ < bytes_.size() && !is_space(bytes_[pos_])) ++pos_;
    return bytes_.substr(start, pos_ - start);
  }

  std::string_view bytes_;
  std::size_t pos_;
  int line_;
};

// Data source for binary files, either byte order; byte offsets for messages.
class BinarySource {
 public:
  BinarySource(std::string_view bytes, std::size_t pos, bool big_endian)
      : bytes_(bytes), pos_(pos), swap_(big_endian) {}

  std::size_t min_bytes(ScalarType type) const { return scalar_type_size(type); }
  std::size_t remaining() const { return bytes_.size() - pos_; }

  template <typename T>
  T read(const Place& place) {
    if (bytes_.size() - pos_ < sizeof(T))
      fail("truncated binary data at byte " + std::to_string(pos_) + ": missing " + place.text());
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, bytes_.data() + pos_, sizeof(T));
    if (swap_)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    pos_ += sizeof(T);
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  void expect_end() const {
    if (pos_ < bytes_.size())
      fail(std::to_string(bytes_.size() - pos_) +
           " unexpected bytes after the last element at byte " + std::to_string(pos_) +
           " (do the header's element counts match the data?)");
  }

 private:
  std::string_view bytes_;
  std::size_t pos_;
  bool swap_;
};

// Refuses counts the remaining bytes cannot hold, before anything is allocated.
template <typename Source>
void check_count_fits(const PlyElement& e, const Source& source) {
  std::size_t per_element = 0;
  for (const PlyProperty& p : e.properties)
    per_element += source.min_bytes(p.is_list ? p.count_type : p.type());
  if (per_element > 0 && e.count > source.remaining() / per_element)
    fail("the header declares " + std::to_string(e.count) + " '" + e.name +
         "' elements, but only " + std::to_string(source.remaining()) +
         " bytes of data remain (wrong count or truncated file)");
}

// The list length of item i of list property p.
template <typename Source>
std::size_t read_list_length(Source& source, const PlyElement& e, std::size_t i,
                             const PlyProperty& p) {
  const double n = with_scalar_type(p.count_type, [&](auto count) {
    return static_cast<double>(source.template read<decltype(count)>(Place{e, i, p, true}));
  });
  if (n < 0) fail("negative list length of " + Place{e, i, p, false}.text());
  const auto length = static_cast<std::size_t>(n);
  if (length > source.remaining() / source.min_bytes(p.type()))
    fail("list length " + std::to_string(length) + " of " + Place{e, i, p, false}.text() +
         " exceeds the remaining data (truncated or corrupt file)");
  return length;
}

// Reads item i's entry of property p (a value, or a list) onto `column`, p's typed values.
template <typename Source, typename T>
void read_entry(Source& source, const PlyElement& e, std::size_t i, PlyProperty& p,
                std::vector<T>& column) {
  if (!p.is_list) {
    column.push_back(source.template read<T>(Place{e, i, p, false}));
    return;
  }
  const std::size_t length = read_list_length(source, e, i, p);
  for (std::size_t k = 0; k < length; ++k)
    column.push_back(source.template read<T>(Place{e, i, p, false}));
  p.offsets.push_back(column.size());
}

template <typename Source>
void read_element(PlyElement& e, Source& source) {
  if (e.properties.empty()) return;  // nothing stored, nothing to read
  check_count_fits(e, source);
  for (PlyProperty& p : e.properties) {
    p.values.reserve(e.count);
    if (p.is_list) p.offsets.assign(1, 0);
  }
  for (std::size_t i = 0; i < e.count; ++i)
    for (PlyProperty& p : e.properties)
      p.values.visit([&](auto& column) { read_entry(source, e, i, p, column); });
}

template <typename Source>
void read_body(PlyTables& ply, Source source) {
  for (PlyElement& e : ply.elements) read_element(e, source);
  source.expect_end();
}

int count_lines(std::string_view bytes, std::size_t end) {
  int lines = 1;
  for (std::size_t i = 0; i < end; ++i)
    if (bytes[i] == '\n') ++lines;
  return lines;
}

}  // namespace

PlyTables parse_ply_tables(std::string_view bytes) {
  PlyTables ply;
  const std::size_t data = parse_header(bytes, ply);
  if (ply.format == PlyFormat::Ascii)
    read_body(ply, AsciiSource(bytes, data, count_lines(bytes, data)));
  else
    read_body(ply, BinarySource(bytes, data, ply.format == PlyFormat::BinaryBigEndian));
  return ply;
}

}  // namespace qd::io
