// printf-style formatting into a std::string, for the adapters' log lines and messages.
#pragma once

#include <cstdarg>
#include <cstdio>
#include <string>

namespace qdml {

__attribute__((format(printf, 1, 2))) inline std::string format(const char* fmt, ...) {
  char buffer[512];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buffer, sizeof buffer, fmt, args);
  va_end(args);
  return buffer;
}

}  // namespace qdml
