// The Python module's parameters: which declared parameters a job takes from Python (all but
// those about files, which arrays replace), and a job's settings from the keyword
// arguments. Each value is checked against its declaration (type, range, choices) and a bad
// one, or a name the job does not declare, throws qd::common::Error naming the parameter.
#pragma once

#include <map>
#include <string>
#include <variant>
#include <vector>

#include "param.h"

namespace qd::python {

// A keyword argument as the Python side passes it: a number (bool as 0/1) or a text.
using Given = std::map<std::string, params::Value>;

// True when Python has parameter p.
bool in_python(const params::ParamInfo& p);

// The value v for parameter p, checked; else qd::common::Error naming p.
params::Value checked_value(const params::ParamInfo& p, const params::Value& v);

// The settings S{} with each given value set, checked; else qd::common::Error.
template <typename S>
S settings_from(const std::vector<params::Param<S>>& declared, const Given& given) {
  S settings;
  for (const auto& [name, value] : given) {
    const params::Param<S>* found = nullptr;
    for (const params::Param<S>& p : declared)
      if (p.name == name && in_python(p)) found = &p;
    if (!found) throw common::Error("unknown parameter '" + name + "'");
    try {
      found->set(settings, checked_value(*found, value));
    } catch (const params::ParamError& e) {
      throw common::Error(name + " " + e.what());
    }
  }
  return settings;
}

}  // namespace qd::python
