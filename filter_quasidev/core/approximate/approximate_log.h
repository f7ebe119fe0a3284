// The text the approximation gives its user: a line per patch, the total, the stop reasons and
// the race of Developability::Auto. Only the log and the reports' strings are made here.
#pragma once

#include <string>
#include <vector>

#include "approximate/deformer.h"
#include "approximate/patch_fit.h"
#include "approximate/result.h"
#include "approximate/term_race.h"

namespace qd {

const char* term_name(Term t);

// Why a patch takes its term; the race's figures when it was measured.
std::string term_reason_text(const PatchFit& p, const std::vector<CandidateReport>& candidates);

// The candidates of a race with their G_ABD reduction from `initial_g`.
std::vector<CandidateReport> candidate_reports(const std::vector<CandidateFigures>& race,
                                               double initial_g);

// Why a run stopped, with the figure that decided.
std::string stop_text(const DeformOutcome& o, const Params& params);

// One line per patch: its size, Step 1 fit, term and why, iterations and why they stopped,
// G_ABD before → after, the last iteration's ratios (Eqs. 19–20), displacement, time.
std::string patch_log_line(const PatchReport& p, double ae);

std::string total_log_line(const Result& r);

// When the run removed less than half of the curvature: why, with the figures the engine has,
// and what to try. held_share: percent of the input's G_ABD on interior vertices that no group
// moved (fixed seams, the kept boundary, the selection).
std::vector<std::string> advice(const Result& r, const Params& params, double held_share);

}  // namespace qd
