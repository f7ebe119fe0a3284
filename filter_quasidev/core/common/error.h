// The one exception type the engine throws: its message is written for the user
// (what was wrong and what to do), and adapters show it verbatim.
#pragma once

#include <stdexcept>
#include <string>

namespace qd::common {

struct Error : std::runtime_error {
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace qd::common
