// The options a subcommand gets from its job's declared parameters (params/*_params.h): each
// parameter of the command is --name (with '-' for '_') plus its older spellings; a Boolean is
// a pair --name / --no-name. A value is checked against the parameter's type and range, and a
// bad one throws UsageError naming the option, the value and what it must be.
#pragma once

#include <string>
#include <vector>

#include "option_values.h"
#include "param.h"

namespace CLI {
class App;
}

namespace qd::cli {

// The value of the option `option` (parameter p) from its text, checked; else UsageError.
params::Value declared_value(const params::ParamInfo& p, const std::string& option,
                             const std::string& text);

// CLI11's name list of an option: its spelling, then its older ones ("--a,--b").
std::string option_names(const std::string& spelling, const std::vector<std::string>& older);

// How --help shows the value of parameter p ("X", "N", "NAME", "ID=X[,ID=X...]", "FILE.svg").
std::string value_name(const params::ParamInfo& p);

// The --help text of parameter p: its help wrapped, then its unit, range, choices and default.
std::string declared_help(const params::ParamInfo& p);

// Registers on job one option per parameter of `declared` that the command has, each storing
// its value in `settings` (the last occurrence wins; a Text list adds up).
template <typename S>
void add_declared_options(CLI::App& job, const std::vector<params::Param<S>>& declared,
                          S& settings) {
  for (const params::Param<S>& p : declared) {
    if (!(p.fronts & params::kCommand)) continue;
    const std::string option = params::option_name(p.name);
    if (p.type == params::Type::Boolean) {
      const bool on = std::get<double>(p.default_value) != 0;
      flag(job, option_names(option, p.aliases), declared_help(p),
           [&p, &settings] { p.set(settings, 1.0); });
      flag(job, option_names("--no-" + option.substr(2), p.off_aliases),
           "the opposite of " + option + (on ? "" : " (default)"),
           [&p, &settings] { p.set(settings, 0.0); });
      continue;
    }
    valued(job, option_names(option, p.aliases), value_name(p), declared_help(p),
           [&p, &settings, option](const std::string& text) {
             const params::Value value = declared_value(p, option, text);
             try {
               p.set(settings, value);
             } catch (const params::ParamError& e) {
               usage(option + " " + e.what());
             }
           });
  }
}

}  // namespace qd::cli
