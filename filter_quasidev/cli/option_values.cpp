#include "option_values.h"

#include <CLI/CLI.hpp>
#include <cmath>

#include "io/text_scan.h"

namespace qd::cli {

void usage(const std::string& message) { throw UsageError(message + " (see quasidev --help)"); }

double number(const std::string& option, const std::string& text) {
  double v = 0;
  if (!io::parse_number(text, v) || !std::isfinite(v))
    usage(option + " expects a finite number, got '" + text + "'");
  return v;
}

int whole_number(const std::string& option, const std::string& text, long long lo, long long hi) {
  long long v = 0;
  if (!io::parse_integer(text, v) || v < lo || v > hi)
    usage(option + " expects a whole number from " + std::to_string(lo) + " to " +
          std::to_string(hi) + ", got '" + text + "'");
  return static_cast<int>(v);
}

void valued(CLI::App& job, const std::string& name, const std::string& value_name,
            const std::string& description, std::function<void(const std::string&)> set) {
  job.add_option_function<std::string>(name, std::move(set), description)
      ->option_text(value_name)
      ->trigger_on_parse();
}

void flag(CLI::App& job, const std::string& name, const std::string& description,
          std::function<void()> set) {
  job.add_flag_callback(name, std::move(set), description)->trigger_on_parse();
}

const char* const kInputHelp =
    "PLY (ascii or binary), OBJ or OFF. Patches come from the PLY\n"
    "face `quality` (rounded; else an integer face `patch`) or OBJ\n"
    "`g`/`o` groups; without them the whole mesh is one patch.";

void add_job_options(CLI::App& job, JobOptions& o, const std::string& input_help,
                     const std::string& output_help, const std::string& report_help) {
  job.add_option("INPUT", o.input, input_help)->required()->type_name("");
  job.add_option("OUTPUT", o.output, output_help)->required()->type_name("");
  valued(job, "--report", "FILE.json", report_help, [&o](const std::string& v) { o.report = v; });
  flag(job, "--overwrite-input", "allow OUTPUT to be the INPUT file",
       [&o] { o.overwrite_input = true; });
  flag(job, "--progress",
       "show a progress line on stderr (default: when stderr is a\nterminal and not --quiet)",
       [&o] { o.progress = ProgressMode::On; });
  flag(job, "--no-progress", "never show the progress line",
       [&o] { o.progress = ProgressMode::Off; });
  flag(job, "--quiet", "print neither the log (stdout) nor notes (stderr)",
       [&o] { o.quiet = true; });
}

}  // namespace qd::cli
