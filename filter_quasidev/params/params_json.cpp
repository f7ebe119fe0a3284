#include "params_json.h"

#include <cmath>

namespace qd::params {

namespace {

const char* type_name(Type t) {
  switch (t) {
    case Type::Real:
      return "real";
    case Type::Integer:
      return "integer";
    case Type::Boolean:
      return "boolean";
    case Type::Choice:
      return "choice";
    case Type::Text:
      return "text";
    case Type::SaveFile:
      return "save_file";
  }
  return "";
}

Json bound(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

const char* front_name(unsigned fronts) {
  return fronts == kBoth ? "both" : fronts == kCommand ? "command" : "filters";
}

}  // namespace

Json value_json(const ParamInfo& p, const Value& v) {
  if (const auto* text = std::get_if<std::string>(&v)) return *text;
  const double x = std::get<double>(v);
  if (p.type == Type::Boolean) return x != 0;
  if (p.type == Type::Integer) return static_cast<long long>(std::llround(x));
  return x;
}

Json declaration_json(const std::vector<ParamInfo>& params) {
  Json out = Json::array();
  for (const ParamInfo& p : params)
    out.push_back({{"name", p.name},
                   {"option", option_name(p.name)},
                   {"aliases", p.aliases},
                   {"off_aliases", p.off_aliases},
                   {"type", type_name(p.type)},
                   {"unit", unit_name(p.unit)},
                   {"min", bound(p.range.min)},
                   {"max", bound(p.range.max)},
                   {"min_open", p.range.min_open},
                   {"max_open", p.range.max_open},
                   {"choices", p.choices},
                   {"default", value_json(p, p.default_value)},
                   {"label", p.label},
                   {"help", p.help},
                   {"value_name", p.value_name},
                   {"extension", p.extension},
                   {"fronts", front_name(p.fronts)},
                   {"why_not", p.why_not}});
  return out;
}

}  // namespace qd::params
