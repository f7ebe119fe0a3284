// format_text: printf-style text into a std::string of any length (std::vsnprintf, measured first).
// The one way to make text that carries numbers (docs/development.md, "Making text"):
//  - text with numbers: format_text, whose format decides every digit ("%g" is what
//    `ostream << double` prints, "%.2f" what std::fixed with std::setprecision(2) prints);
//  - std::to_string only for a lone integer (it prints what "%d" prints);
//  - std::ostream only to write a file or a stream, never to build a std::string.
// The format attribute lets -Wall -Werror check every argument against its format. Numbers are
// written in the C locale, which every front end keeps (MeshLab sets it at start-up).
#pragma once

#include <cstdarg>
#include <cstdio>
#include <string>

namespace qd::common {

inline std::string format_text(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

inline std::string format_text(const char* fmt, ...) {
  va_list args;
  va_start(args, fmt);
  va_list measure;
  va_copy(measure, args);
  const int length = std::vsnprintf(nullptr, 0, fmt, measure);
  va_end(measure);
  std::string text(length > 0 ? static_cast<std::size_t>(length) : 0, '\0');
  if (length > 0) std::vsnprintf(text.data(), text.size() + 1, fmt, args);
  va_end(args);
  return text;
}

}  // namespace qd::common
