// A value of each declared parameter other than its default and within its range: what the
// tests set through each front end (the command, the MeshLab adapter) to check that it reaches
// the job's settings. A new Text parameter needs its example here.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/format_text.h"
#include "param.h"

namespace qd::params::test {

inline Value sample_value(const ParamInfo& p) {
  switch (p.type) {
    case Type::Real: {
      const double d = std::get<double>(p.default_value);
      for (const double v : {2 * d + 1, d / 2, p.range.min + 0.125, p.range.max - 0.125})
        if (std::isfinite(v) && v != d && range_violation(p.range, v).empty()) return v;
      break;
    }
    case Type::Integer: {
      const double d = std::get<double>(p.default_value);
      return range_violation(p.range, d + 1).empty() ? d + 1 : d - 1;
    }
    case Type::Boolean:
      return std::get<double>(p.default_value) != 0 ? 0.0 : 1.0;
    case Type::Choice:
      for (const std::string& c : p.choices)
        if (Value(c) != p.default_value) return c;
      break;
    case Type::Text:
      if (p.name == "patch_tolerance_ae") return std::string("2=0.5,7=3");
      if (p.name == "constraints_file") return std::string("fixed.txt");
      if (p.name == "grain_direction") return std::string("0,0,1");
      break;
    case Type::SaveFile:
      return "pattern" + p.extension;
  }
  ADD_FAILURE() << p.name << ": no sample value (add one to param_samples.h)";
  return p.default_value;
}

// The sample as the command line writes it.
inline std::string sample_text(const ParamInfo& p) {
  const Value v = sample_value(p);
  if (const auto* text = std::get_if<std::string>(&v)) return *text;
  return common::format_text("%.17g", std::get<double>(v));
}

}  // namespace qd::params::test
