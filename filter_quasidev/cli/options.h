// The command line of `quasidev`, parsed with CLI11: the subcommands `approximate` (also the job
// when no subcommand is named, so `quasidev INPUT OUTPUT [options]` works as it always has) and
// `segment` and `flatten`, each with the files every job has and the options of its declared
// parameters (params/, with their defaults), --help and --version. Bad command lines throw
// UsageError (exit status 2) naming the option, the bad value and what to do.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "approximate_settings.h"
#include "common/error.h"
#include "flatten_settings.h"
#include "segment_settings.h"

namespace qd::cli {

struct UsageError : common::Error {
  using Error::Error;
};

enum class ProgressMode { Auto, On, Off };

// What every job reads and writes, and how it talks.
struct JobOptions {
  std::string input;
  std::string output;
  std::string report;  // empty = no JSON report
  ProgressMode progress = ProgressMode::Auto;
  bool quiet = false;
  bool overwrite_input = false;
};

// The options of each subcommand: the files and the settings of its job.
struct ApproximateOptions : JobOptions {
  params::ApproximateSettings settings;
};

struct SegmentOptions : JobOptions {
  params::SegmentSettings settings;
};

struct FlattenOptions : JobOptions {
  params::FlattenSettings settings;
};

// The files a job writes, named as on its command line ("OUTPUT", "--report", ...), the given
// ones only.
std::vector<std::pair<std::string, std::string>> output_files(const JobOptions& o);
std::vector<std::pair<std::string, std::string>> output_files(const FlattenOptions& o);

enum class Job { Approximate, Segment, Flatten };

// What the command line asks for: text to print on stdout before exiting with status 0 (--help,
// --version), or else the job to run with its options.
struct CommandLine {
  std::string print;
  Job job = Job::Approximate;
  ApproximateOptions approximate;
  SegmentOptions segment;
  FlattenOptions flatten;
};

// args: argv without the program name.
CommandLine parse_command_line(std::vector<std::string> args);

}  // namespace qd::cli
