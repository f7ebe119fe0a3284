#include "python_settings.h"

#include <algorithm>
#include <cmath>

namespace qd::python {

bool in_python(const params::ParamInfo& p) {
  // The command's file of fixed vertices, the output mesh's quality and colour, and the pattern
  // files' style, unit, paper and marker: the `fixed` argument and the returned arrays take
  // their place.
  static const std::vector<std::string> file_only = {
      "constraints_file", "output_quality", "colorize", "dxf_style", "unit", "paper",
      "marker_width"};
  return p.type != params::Type::SaveFile &&
         std::find(file_only.begin(), file_only.end(), p.name) == file_only.end();
}

params::Value checked_value(const params::ParamInfo& p, const params::Value& v) {
  using params::Type;
  const bool number = std::holds_alternative<double>(v);
  const bool wants_number =
      p.type == Type::Real || p.type == Type::Integer || p.type == Type::Boolean;
  if (number != wants_number)
    throw common::Error(p.name + (wants_number ? " expects a number" : " expects a string"));
  if (p.type == Type::Real || p.type == Type::Integer) {
    const double x = std::get<double>(v);
    std::string wrong = params::range_violation(p.range, x);
    if (wrong.empty() && p.type == Type::Integer && x != std::floor(x))
      wrong = "must be a whole number";
    if (!wrong.empty())
      throw common::Error(p.name + " " + wrong + ", got " + params::number_text(x));
  }
  if (p.type == Type::Choice &&
      std::find(p.choices.begin(), p.choices.end(), std::get<std::string>(v)) == p.choices.end()) {
    std::string names;
    for (const std::string& c : p.choices) names += (names.empty() ? "" : ", ") + c;
    throw common::Error(p.name + " must be one of " + names + ", got '" + std::get<std::string>(v) +
                        "'");
  }
  return v;
}

}  // namespace qd::python
