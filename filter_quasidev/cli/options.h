// Command-line options of `quasidev` and its --help text.
// Input: argv. Output: an Options value whose defaults come from qd::Params (so the command,
// the plugins and the help text never disagree). Throws UsageError (exit status 2) for an
// unknown option, a missing or malformed value, or an out-of-range parameter.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "approximate/params.h"
#include "common/error.h"

namespace qd::cli {

struct UsageError : Error {
  using Error::Error;
};

// Default δ_err in units of the input's average edge length AE (Params::tolerance is in model
// units and is set from this once AE is known).
constexpr double kDefaultToleranceAE = 1.0;

enum class QualityKind { Curvature, Displacement };
enum class ProgressMode { Auto, On, Off };

struct Options {
  std::string input;
  std::string output;
  std::string report;                        // empty = no JSON report
  std::string constraints;                   // empty = no constraint file
  double tolerance_ae = kDefaultToleranceAE;
  std::map<int, double> patch_tolerance_ae;  // per patch id, AE units
  Params params;                             // tolerance fields are set later from AE
  QualityKind quality = QualityKind::Curvature;
  bool color = true;
  ProgressMode progress = ProgressMode::Auto;
  bool quiet = false;
  bool overwrite_input = false;
  bool help = false;
  bool version = false;
};

Options parse_options(const std::vector<std::string>& args);

std::string help_text();

}  // namespace qd::cli
