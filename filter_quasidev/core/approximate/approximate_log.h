// The log the approximation gives its user, made from the Result's enums and numbers
// (report_text.h words them).
#pragma once

#include <string>
#include <vector>

#include "approximate/params.h"
#include "approximate/result.h"
#include "approximate/setting_text.h"

namespace qd::approximate {

// The log of a solve: its warnings, the patches solved in another's group (r.joins), the rounds
// solved again (solve_schedule.h), a line per patch, the total and, when little was removed,
// advice. held_share: percent of the input's G_ABD on interior vertices that no group moved.
std::vector<std::string> approximate_log(const Result& r,
                                         const std::vector<std::vector<int>>& reruns,
                                         const Params& params, double held_share);

// The note of a mesh solved both with the patches that have more of their curvature on their
// seams than inside joined to a neighbour and with their seams held, and which was kept.
std::string join_trial_note(const JoinTrial& trial);

// The note of a mesh without patch ids that the engine split into `count` patches.
std::string segmented_note(const std::string& why, int count, const SettingText& setting);

// One line per patch: its size, Step 1 fit, term and why, iterations and why they stopped,
// G_ABD before → after, the last iteration's ratios (Eqs. 19–20), displacement, time.
std::string patch_log_line(const PatchReport& p, double ae);

}  // namespace qd::approximate
