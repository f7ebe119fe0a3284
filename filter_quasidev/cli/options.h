// The command line of `quasidev`, parsed with CLI11: the subcommands `approximate` (also the job
// when no subcommand is named, so `quasidev INPUT OUTPUT [options]` works as it always has) and
// `segment` and `flatten`, their options with their defaults from qd::Params, qd::SegmentParams
// and qd::FlattenParams, --help and --version. Bad command lines throw UsageError (exit status 2) naming the option, the bad value
// and what to do.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "approximate/params.h"
#include "common/error.h"
#include "flatten/flatten_problem.h"
#include "option_choices.h"
#include "segment/segment_params.h"

namespace qd::cli {

struct UsageError : Error {
  using Error::Error;
};

// Default δ_err in units of the input's average edge length AE (Params::tolerance is in model
// units and is set from this once AE is known).
constexpr double kDefaultToleranceAE = 1.0;

enum class ProgressMode { Auto, On, Off };

// What every job reads and writes, and how it talks.
struct JobOptions {
  std::string input;
  std::string output;
  std::string report;                        // empty = no JSON report
  ProgressMode progress = ProgressMode::Auto;
  bool quiet = false;
  bool overwrite_input = false;
};

// The options of `quasidev approximate`.
struct ApproximateOptions : JobOptions {
  std::string constraints;                   // empty = no constraint file
  double tolerance_ae = kDefaultToleranceAE;
  std::map<int, double> patch_tolerance_ae;  // per patch id, AE units
  Params params;                             // tolerance fields are set later from AE
  QualityKind quality = QualityKind::Curvature;
  bool color = true;
};

// The options of `quasidev segment`.
struct SegmentOptions : JobOptions {
  SegmentParams params;
  bool keep_patches = false;  // existing patch ids are regions of their own, kept where they fit
};

// The options of `quasidev flatten`.
struct FlattenOptions : JobOptions {
  std::string svg;                           // empty = no SVG pattern
  std::string dxf;                           // empty = no DXF pattern
  PatternUnit unit = PatternUnit::Model;
  FlattenParams params;
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
