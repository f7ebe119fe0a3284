// The reports of a solve, in enums and numbers: per patch its fit, its term and why, the stop
// of each pass and its iterations (the figures are measured after, patch_figures.h).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "approximate/result.h"
#include "approximate/solve_schedule.h"

namespace qd::approximate {

struct SolveReports {
  std::map<int, PatchReport> patches;  // by patch id
  std::vector<Vec3> initial_target;    // per face: its first run's initial target
  StageTimes times;                    // summed over the runs made here (not reused), replaced too
  size_t unfitted = 0;                 // patches Step 1 could not fit in their first run
  int first_unfitted = -1;             // the first of them, and why Step 1 could not fit it
  std::string first_unfitted_why;
};

SolveReports patch_reports(const SolveSchedule& s, const Params& params, size_t faces);

}  // namespace qd::approximate
