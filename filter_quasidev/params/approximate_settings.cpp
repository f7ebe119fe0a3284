#include "approximate_settings.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "declare.h"

namespace qd::params {

namespace {

template <typename T>
bool parse(const std::string& text, T& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end;
}

std::string exact_text(double v) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return ec == std::errc() ? std::string(buffer, end) : std::string("?");
}

// One ID=X item into `into`.
void parse_item(const std::string& item, std::map<int, double>& into) {
  const std::size_t eq = item.find('=');
  long long id = 0;
  double x = 0;
  if (eq == std::string::npos || !parse(item.substr(0, eq), id) || std::llabs(id) > 1000000000 ||
      !parse(item.substr(eq + 1), x))
    throw ParamError("expects ID=X items (e.g. 3=0.05), got '" + item + "'");
  const std::string wrong = range_violation(greater_than(0), x);
  if (!wrong.empty())
    throw ParamError("for patch " + std::to_string(id) + " " + wrong + ", got " +
                     item.substr(eq + 1));
  into[static_cast<int>(id)] = x;
}

}  // namespace

Params engine_params(const ApproximateSettings& s, double average_edge,
                     const std::vector<int>& patch) {
  Params p = s.engine;
  p.tolerance = s.tolerance_model > 0 ? s.tolerance_model : s.tolerance_ae * average_edge;
  p.patch_tolerance.clear();
  for (const auto& [id, x] : s.patch_tolerance_ae) {
    if (std::find(patch.begin(), patch.end(), id) == patch.end() && !(patch.empty() && id == 0))
      throw ParamError("names patch " + std::to_string(id) + ", which the mesh does not have");
    p.patch_tolerance[id] = x * average_edge;
  }
  return p;
}

std::string patch_tolerance_text(const std::map<int, double>& tolerances) {
  std::string text;
  for (const auto& [id, x] : tolerances)
    text += (text.empty() ? "" : ",") + std::to_string(id) + "=" + exact_text(x);
  return text;
}

void parse_patch_tolerance(const std::string& text, std::map<int, double>& into) {
  std::string item;
  for (const char c : text + ",") {
    if (c == ',' || std::isspace(static_cast<unsigned char>(c))) {
      if (!item.empty()) parse_item(item, into);
      item.clear();
    } else {
      item += c;
    }
  }
}

}  // namespace qd::params
