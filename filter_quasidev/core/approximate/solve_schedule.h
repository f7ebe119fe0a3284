// The schedule of a solve: its passes, the rounds of each pass (solve_rounds.h) and the re-runs
// the never-worse rule asks for (§5.4; a group run again races its terms again, from where its
// neighbours left it, so its term and its reported candidates come from the run that stands).
// One pass with fixed seams (the paper). Free seams take
// three, each starting where the one before ended, so none can undo another: all patches in
// one group (its one step scale is set by the worst patch; Developability::Auto races one term
// for all of them), then each solve group with its seams held (where Auto measures each patch's
// own term, which the last pass keeps), then each again moving its seam vertices (moved by one
// group, seen by the next, so they stay shared). Under Auto, a mesh above
// kMaxDefectRaceVertices skips the first: in one group that large Auto races no term and would
// run the curve term alone, a choice it did not measure, while the later passes race each
// patch's terms. On generated closed shapes of 80k–100k faces the runs without it took 0.21–0.78
// of the time and left as little or less G_ABD on 7 of 10, moving vertices 2–11 times less far
// on four (docs/performance.md, "Closed meshes").
#pragma once

#include <vector>

#include "approximate/common_names.h"
#include "approximate/group_run.h"
#include "approximate/result.h"
#include "common/progress.h"

namespace qd::approximate {

struct ScheduledRun {
  GroupRun run;
  SolvePass pass = SolvePass::Only;
  // Ran with no term decided for its patches by an earlier pass: a run of the same faces in the
  // same pass, from the same positions under the same constraints, repeats it exactly.
  bool fresh = false;
  bool reused = false;  // taken from another solve's fresh run (its time is counted there)
};

struct SolveSchedule {
  Positions V;                           // the positions after the last pass
  std::vector<ScheduledRun> runs;        // the groups' last runs, pass by pass
  std::vector<std::vector<int>> reruns;  // the patch ids of each round solved again in turn
  std::vector<ScheduledRun> replaced;    // fresh runs of groups that then ran again
  StageTimes replaced_times;             // the work of every run made here that was replaced
};

// Free seams skip the pass of all patches at once (above): Auto on a mesh of more than
// kMaxDefectRaceVertices vertices.
bool skips_all_at_once(const Params& params, Eigen::Index vertices);

// group: solve group per face (solve_groups.h); constrained: per vertex, held with free seams;
// held: held with fixed seams; earlier: fresh runs of another solve of the same input (a join
// trial's other grouping), taken instead of running a group they repeat.
SolveSchedule run_schedule(const SolveInput& in, const std::vector<int>& group,
                           const std::vector<char>& constrained, const std::vector<char>& held,
                           const std::vector<ScheduledRun>& earlier, const Progress& progress);

// A grouping of the mesh into solve groups under fixed seams: the input its groups run from,
// the solve group of each face and the vertices held.
struct Grouping {
  const SolveInput& in;
  const std::vector<int>& group;
  const std::vector<char>& held;
};

// Under fixed seams a solve runs each of its groups once, from the input, in its one pass
// (unless the never-worse rule runs some again). Those runs of several groupings of one mesh (a
// join trial's, quasidev.h) are made here at once, a group that two groupings share once, so
// that no grouping's groups wait for another's to end; run_schedule takes them as `earlier`.
std::vector<ScheduledRun> first_runs(const std::vector<Grouping>& groupings,
                                     const Progress& progress);

// The fresh runs of a schedule, those of groups that ran again included: what another
// grouping's run_schedule takes as `earlier`.
std::vector<ScheduledRun> fresh_runs(SolveSchedule&& s);

}  // namespace qd::approximate
