// The pieces every subcommand's options are made of: converting an option's text to a checked
// value (a bad one throws UsageError naming the option, the value and what to do) and
// registering options with CLI11 so that each occurrence is converted in order (the last one
// wins), plus the options every job shares (files, report, progress, quiet).
#pragma once

#include <functional>
#include <string>

#include "options.h"

namespace CLI {
class App;
}

namespace qd::cli {

[[noreturn]] void usage(const std::string& message);

double number(const std::string& option, const std::string& text);  // finite
// A whole number in [lo, hi].
int whole_number(const std::string& option, const std::string& text, long long lo, long long hi);

// An option with a value, shown as `name value_name`; `set` converts each occurrence.
void valued(CLI::App& job, const std::string& name, const std::string& value_name,
            const std::string& description, std::function<void(const std::string&)> set);

void flag(CLI::App& job, const std::string& name, const std::string& description,
          std::function<void()> set);

// The help text of INPUT that every job shares: formats and where patches come from.
extern const char* const kInputHelp;

// INPUT and OUTPUT (required, described by input_help and output_help), --report (described by
// report_help), --overwrite-input, --progress, --no-progress and --quiet.
void add_job_options(CLI::App& job, JobOptions& o, const std::string& input_help,
                     const std::string& output_help, const std::string& report_help);

}  // namespace qd::cli
