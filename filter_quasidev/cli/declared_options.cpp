#include "declared_options.h"

#include <algorithm>

namespace qd::cli {

namespace {

constexpr std::size_t kHelpWidth = 62;  // the description column of --help

// text broken into lines of at most kHelpWidth characters at spaces.
std::string wrap(const std::string& text) {
  std::string out, line;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (!line.empty() && line.size() + 1 + word.size() > kHelpWidth) {
      out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  return out + line;
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : "|") + w;
  return out;
}

}  // namespace

params::Value declared_value(const params::ParamInfo& p, const std::string& option,
                             const std::string& text) {
  using params::Type;
  switch (p.type) {
    case Type::Real: {
      const double v = number(option, text);
      const std::string wrong = params::range_violation(p.range, v);
      if (!wrong.empty()) usage(option + " " + wrong + ", got " + text);
      return v;
    }
    case Type::Integer: {
      const auto lo = static_cast<long long>(p.range.min), hi = static_cast<long long>(p.range.max);
      return static_cast<double>(whole_number(option, text, lo, hi));
    }
    case Type::Boolean:
      return text == "0" ? 0.0 : 1.0;  // flags only: never given as text
    case Type::Choice:
      if (std::find(p.choices.begin(), p.choices.end(), text) == p.choices.end())
        usage(option + " expects " + joined(p.choices) + ", got '" + text + "'");
      return text;
    case Type::Text:
    case Type::SaveFile:
      return text;
  }
  return text;
}

std::string option_names(const std::string& spelling, const std::vector<std::string>& older) {
  std::string names = spelling;
  for (const std::string& o : older) names += "," + o;
  return names;
}

std::string value_name(const params::ParamInfo& p) {
  switch (p.type) {
    case params::Type::Real:
      return "X";
    case params::Type::Integer:
      return "N";
    case params::Type::Choice:
      return "NAME";
    case params::Type::Boolean:
    case params::Type::Text:
    case params::Type::SaveFile:
      return p.value_name;
  }
  return "";
}

std::string declared_help(const params::ParamInfo& p) {
  std::vector<std::string> facts;
  if (p.type == params::Type::Choice) facts.push_back("one of " + joined(p.choices));
  const std::string unit = params::unit_name(p.unit), range = params::range_text(p.range);
  if (!unit.empty() && p.type != params::Type::Text) facts.push_back(unit);
  if (!range.empty()) facts.push_back(range);
  const bool on = p.type == params::Type::Boolean && std::get<double>(p.default_value) != 0;
  if (p.type == params::Type::Boolean) {
    if (on) facts.emplace_back("default");
  } else if (!(p.type == params::Type::Text || p.type == params::Type::SaveFile) ||
             !std::get<std::string>(p.default_value).empty()) {
    facts.push_back("default " + params::value_text(p, p.default_value));
  }
  std::string tail;
  for (const std::string& f : facts) tail += (tail.empty() ? "" : "; ") + f;
  return wrap(p.help + (tail.empty() ? "" : " (" + tail + ")"));
}

}  // namespace qd::cli
