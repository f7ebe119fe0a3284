#include "json_writer.h"

#include <cmath>
#include <cstdio>

namespace qd::cli {

namespace {

std::string quoted(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      q += '\\';
      q += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(c));
      q += buffer;
    } else {
      q += c;
    }
  }
  return q + "\"";
}

}  // namespace

void JsonWriter::key_prefix(const char* key) {
  if (!first_) out_ += ',';
  if (depth_ > 0) out_ += '\n' + std::string(static_cast<std::size_t>(depth_) * 2, ' ');
  if (key) out_ += quoted(key) + ": ";
  first_ = false;
}

void JsonWriter::begin_object(const char* key) {
  key_prefix(key);
  out_ += '{';
  ++depth_;
  first_ = true;
}

void JsonWriter::end_object() {
  --depth_;
  if (!first_) out_ += '\n' + std::string(static_cast<std::size_t>(depth_) * 2, ' ');
  out_ += '}';
  first_ = false;
  if (depth_ == 0) out_ += '\n';
}

void JsonWriter::begin_array(const char* key) {
  key_prefix(key);
  out_ += '[';
  ++depth_;
  first_ = true;
}

void JsonWriter::end_array() {
  --depth_;
  if (!first_) out_ += '\n' + std::string(static_cast<std::size_t>(depth_) * 2, ' ');
  out_ += ']';
  first_ = false;
}

void JsonWriter::value(const char* key, double v) {
  key_prefix(key);
  if (!std::isfinite(v)) {
    out_ += "null";
    return;
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  out_ += buffer;
}

void JsonWriter::value(const char* key, int v) {
  key_prefix(key);
  out_ += std::to_string(v);
}

void JsonWriter::value(const char* key, bool v) {
  key_prefix(key);
  out_ += v ? "true" : "false";
}

void JsonWriter::value(const char* key, const std::string& v) {
  key_prefix(key);
  out_ += quoted(v);
}

}  // namespace qd::cli
