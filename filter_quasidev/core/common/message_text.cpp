#include "common/message_text.h"

#include <sstream>

namespace qd::common {

std::string to_text(int n) { return std::to_string(n); }

std::string to_text(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

std::string count_text(int n, const char* one, const char* many) {
  return to_text(n) + " " + (n == 1 ? one : many);
}

}  // namespace qd::common
