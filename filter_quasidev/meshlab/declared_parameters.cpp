#include "declared_parameters.h"

#include <cmath>

namespace qdml {

using qd::params::number_text;

int choice_index(const qd::params::ParamInfo& p, const std::string& value) {
  for (std::size_t k = 0; k < p.choices.size(); ++k)
    if (p.choices[k] == value) return static_cast<int>(k);
  return 0;
}

std::string parameter_title(const qd::params::ParamInfo& p) {
  return p.label + " (" + p.name + ")";
}

qd::params::Value declared_value(const qd::params::ParamInfo& p, const ParamValue& given) {
  using qd::params::Type;
  if (const auto* text = std::get_if<std::string>(&given)) return *text;
  const double v = std::get<double>(given);
  if (p.type == Type::Choice) {
    const long k = std::lround(v);
    if (k < 0 || k >= static_cast<long>(p.choices.size()))
      throw qd::common::Error(parameter_title(p) + " has no value number " + number_text(v));
    return p.choices[static_cast<std::size_t>(k)];
  }
  if (p.type == Type::Real || p.type == Type::Integer) {
    const std::string wrong = qd::params::range_violation(p.range, v);
    if (!wrong.empty())
      throw qd::common::Error(parameter_title(p) + " " + wrong + ", got " + number_text(v));
  }
  return v;
}

}  // namespace qdml
