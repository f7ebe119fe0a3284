// A filter's parameters from its job's declaration (params/): those MeshLab has, and the
// settings from the values MeshLab hands back, checked against the declaration so a bad value
// is refused with a message naming the parameter (label and name) and saying what it must be.
#pragma once

#include <string>
#include <vector>

#include "filter_table.h"
#include "param.h"

namespace qdml {

// The declared parameters the MeshLab filters have, in order.
template <typename S>
std::vector<qd::params::ParamInfo> filter_parameters(
    const std::vector<qd::params::Param<S>>& declared) {
  std::vector<qd::params::ParamInfo> out;
  for (const qd::params::Param<S>& p : declared)
    if (p.fronts & qd::params::kFilters) out.push_back(p);
  return out;
}

// The enum index of a Choice's value name (0 when it is not one of them).
int choice_index(const qd::params::ParamInfo& p, const std::string& value);

// The declared value of p from MeshLab's (a Choice's enum index becomes its name); throws
// qd::common::Error naming p when the value is out of p's range or not one of its choices.
qd::params::Value declared_value(const qd::params::ParamInfo& p, const ParamValue& given);

// "Label (name)", how a message names parameter p.
std::string parameter_title(const qd::params::ParamInfo& p);

// The settings from `values` (a parameter missing there keeps its default); throws
// qd::common::Error naming the first bad parameter.
template <typename S>
S declared_settings(const std::vector<qd::params::Param<S>>& declared, const ParamValues& values) {
  S settings;
  for (const qd::params::Param<S>& p : declared) {
    const auto it = values.find(p.name);
    if (it == values.end() || !(p.fronts & qd::params::kFilters)) continue;
    try {
      p.set(settings, declared_value(p, it->second));
    } catch (const qd::params::ParamError& e) {
      throw qd::common::Error(parameter_title(p) + " " + e.what());
    }
  }
  return settings;
}

// A run of a filter whose settings are read from `values`: job(settings) when they are all
// good, else a failed run saying which parameter is bad.
template <typename S, typename Job>
FilterRun run_declared(const std::vector<qd::params::Param<S>>& declared, const ParamValues& values,
                       Job job) {
  S settings;
  try {
    settings = declared_settings(declared, values);
  } catch (const qd::common::Error& e) {
    FilterRun refused;
    refused.error = e.what();
    return refused;
  }
  return job(settings);
}

}  // namespace qdml
