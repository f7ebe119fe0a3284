// Minimal streaming JSON writer: objects, arrays, strings (escaped), numbers at full precision
// (17 significant digits, so they read back bit-identical; NaN and infinities become null).
#pragma once

#include <string>

namespace qd::cli {

class JsonWriter {
 public:
  void begin_object(const char* key = nullptr);
  void end_object();
  void begin_array(const char* key = nullptr);
  void end_array();
  void value(const char* key, double v);
  void value(const char* key, int v);
  void value(const char* key, bool v);
  void value(const char* key, const std::string& v);
  const std::string& text() const { return out_; }

 private:
  void key_prefix(const char* key);
  std::string out_;
  bool first_ = true;  // no value yet at the current nesting level
  int depth_ = 0;
};

}  // namespace qd::cli
