// The pieces every subcommand's options are made of: converting an option's text to a checked
// value (a bad one throws UsageError naming the option, the value and what to do) and
// registering options with CLI11 so that each occurrence is converted in order (the last one
// wins), plus the options every job shares (files, report, progress, quiet).
#pragma once

#include <functional>
#include <sstream>
#include <string>

#include "option_choices.h"
#include "options.h"

namespace CLI {
class App;
}

namespace qd::cli {

[[noreturn]] void usage(const std::string& message);

double number(const std::string& option, const std::string& text);        // finite
double positive(const std::string& option, const std::string& text);      // > 0
double non_negative(const std::string& option, const std::string& text);  // >= 0
// A whole number in [lo, hi]; `lo_label` names lo in the message (e.g. "0 (all cores)").
int whole_number(const std::string& option, const std::string& text, long long lo, long long hi,
                 const std::string& lo_label);

// " (default X)" as a stream writes X.
template <typename T>
std::string by_default(const T& value) {
  std::ostringstream out;
  out << " (default " << value << ")";
  return out.str();
}

// An option with a value, shown as `name value_name`; `set` converts each occurrence.
void valued(CLI::App& job, const std::string& name, const std::string& value_name,
            const std::string& description, std::function<void(const std::string&)> set);

void flag(CLI::App& job, const std::string& name, const std::string& description,
          std::function<void()> set);

// The value called `text` among `choices`, else UsageError listing them.
template <typename T>
T choice(const std::string& option, const std::string& text, const Choices<T>& choices) {
  std::string names;
  for (const auto& [name, value] : choices) {
    if (text == name) return value;
    names += (names.empty() ? "" : "|") + std::string(name);
  }
  usage(option + " expects " + names + ", got '" + text + "'");
}

// An option of fixed choices; the help shows them and the default (target's value now).
template <typename T>
void choices(CLI::App& job, const std::string& name, const std::string& value_name,
             const std::string& description, const Choices<T>& names, T& target) {
  valued(job, name, value_name, description + by_default(name_of(names, target)),
         [name, &names, &target](const std::string& v) { target = choice(name, v, names); });
}

// The help text of INPUT that every job shares: formats and where patches come from.
extern const char* const kInputHelp;

// INPUT and OUTPUT (required, described by input_help and output_help), --report (described by
// report_help), --overwrite-input, --progress, --no-progress and --quiet.
void add_job_options(CLI::App& job, JobOptions& o, const std::string& input_help,
                     const std::string& output_help, const std::string& report_help);

}  // namespace qd::cli
