// How a front end writes "parameter `name` set to `value`" in the engine's messages: the
// command as its option, MeshLab with the parameter's label. The engine names a parameter by
// its declared snake_case name (filter_quasidev/params/) and never by a front end's spelling.
#pragma once

#include <functional>
#include <string>

namespace qd::approximate {

using SettingText = std::function<std::string(const std::string& name, const std::string& value)>;

// f(name, value), or "name = value" without a front end.
std::string setting_text(const SettingText& f, const std::string& name, const std::string& value);

}  // namespace qd::approximate
