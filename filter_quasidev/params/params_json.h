// Parameters as JSON: the values a job ran with (the reports' "parameters" block, keyed by the
// parameters' names) and the declaration itself (qd_reference --json, which the tests read to
// check the .mlx samples, pymeshlab and the GUI dialog against it).
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "param.h"

namespace qd::params {

using Json = nlohmann::ordered_json;

// v as its parameter's JSON type: a number, a whole number, true/false or a string.
Json value_json(const ParamInfo& p, const Value& v);

// {name: value} of every parameter of `params` in s, in declaration order.
template <typename S>
Json values_json(const std::vector<Param<S>>& params, const S& s) {
  Json out = Json::object();
  for (const Param<S>& p : params) out[p.name] = value_json(p, p.get(s));
  return out;
}

// The declaration: one object per parameter with every field of ParamInfo.
Json declaration_json(const std::vector<ParamInfo>& params);

}  // namespace qd::params
