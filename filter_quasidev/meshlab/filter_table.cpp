#include "filter_table.h"

#include <cmath>

#include "flatten_adapter.h"
#include "quasidev_adapter.h"
#include "segment_adapter.h"

namespace qdml {

double number_value(const ParamValues& values, const std::string& name, double fallback) {
  const auto it = values.find(name);
  return it == values.end() ? fallback : std::get<double>(it->second);
}

int whole_value(const ParamValues& values, const std::string& name, int fallback) {
  return static_cast<int>(std::lround(number_value(values, name, fallback)));
}

bool flag_value(const ParamValues& values, const std::string& name, bool fallback) {
  return number_value(values, name, fallback ? 1.0 : 0.0) != 0;
}

std::string text_value(const ParamValues& values, const std::string& name) {
  const auto it = values.find(name);
  return it == values.end() ? std::string() : std::get<std::string>(it->second);
}

const std::vector<FilterSpec>& filter_table() {
  static const std::vector<FilterSpec> table = {approximate_filter(), segment_filter(), flatten_filter()};
  return table;
}

}  // namespace qdml
