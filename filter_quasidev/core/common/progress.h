// Progress reporting: percent in [0, 100] and a short message. May be empty.
#pragma once

#include <functional>
#include <string>

namespace qd::common {

using Progress = std::function<void(int percent, const std::string& message)>;

}  // namespace qd::common
