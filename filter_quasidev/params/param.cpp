#include "param.h"

#include <algorithm>
#include <cmath>

#include "common/format_text.h"

namespace qd::params {

std::string number_text(double v) { return common::format_text("%g", v); }

std::string option_name(const std::string& name) {
  std::string option = "--" + name;
  std::replace(option.begin(), option.end(), '_', '-');
  return option;
}

std::string range_violation(const Range& r, double v) {
  if (!std::isfinite(v)) return "must be a finite number";
  if (r.min_open ? v <= r.min : v < r.min)
    return r.min_open   ? "must be greater than " + number_text(r.min)
           : r.min == 0 ? std::string("must not be negative")
                        : "must be at least " + number_text(r.min);
  if (r.max_open ? v >= r.max : v > r.max)
    return (r.max_open ? "must be below " : "must be at most ") + number_text(r.max);
  return "";
}

std::string range_text(const Range& r) {
  const bool low = std::isfinite(r.min), high = std::isfinite(r.max);
  if (!low && !high) return "";
  if (!high) return (r.min_open ? "> " : ">= ") + number_text(r.min);
  if (!low) return (r.max_open ? "< " : "<= ") + number_text(r.max);
  return number_text(r.min) + (r.min_open ? " < x " : " <= x ") + (r.max_open ? "< " : "<= ") +
         number_text(r.max);
}

std::string unit_name(Unit u) {
  switch (u) {
    case Unit::None:
      return "";
    case Unit::ModelUnits:
      return "model units";
    case Unit::AverageEdge:
      return "AE";
    case Unit::Degrees:
      return "degrees";
    case Unit::Percent:
      return "%";
    case Unit::Fraction:
      return "fraction";
    case Unit::Faces:
      return "faces";
    case Unit::Iterations:
      return "iterations";
    case Unit::Threads:
      return "threads";
    case Unit::Patches:
      return "patches";
  }
  return "";
}

std::string value_text(const ParamInfo& p, const Value& v) {
  if (const auto* text = std::get_if<std::string>(&v)) return text->empty() ? "none" : *text;
  const double x = std::get<double>(v);
  if (p.type == Type::Boolean) return x != 0 ? "on" : "off";
  return number_text(x);
}

}  // namespace qd::params
