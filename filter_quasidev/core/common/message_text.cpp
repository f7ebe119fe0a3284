#include "common/message_text.h"

#include "common/format_text.h"

namespace qd::common {

std::string to_text(int n) { return std::to_string(n); }

std::string to_text(double x) { return format_text("%g", x); }

std::string count_text(int n, const char* one, const char* many) {
  return to_text(n) + " " + (n == 1 ? one : many);
}

}  // namespace qd::common
