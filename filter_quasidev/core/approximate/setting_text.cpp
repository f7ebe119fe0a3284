#include "approximate/setting_text.h"

namespace qd::approximate {

std::string setting_text(const SettingText& f, const std::string& name, const std::string& value) {
  return f ? f(name, value) : name + " = " + value;
}

}  // namespace qd::approximate
