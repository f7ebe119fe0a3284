// Algorithm 1 of the paper over a whole mesh: validation, solve groups (solve_groups.h), the
// schedule of passes and rounds (solve_schedule.h) running Step 1 and Step 2 per group
// (group_run.h), then the reports (patch_reports.h, patch_figures.h) and the log.
#include "approximate/quasidev.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <string>

#include "approximate/approximate_log.h"
#include "approximate/common_names.h"
#include "approximate/group_mesh.h"
#include "approximate/patch_figures.h"
#include "approximate/patch_reports.h"
#include "approximate/segment_first.h"
#include "approximate/solve_groups.h"
#include "approximate/solve_schedule.h"
#include "approximate/validate.h"
#include "common/error.h"
#include "common/stage_timer.h"
#include "common/thread_count.h"
#include "common/topology.h"

namespace qd::approximate {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// A solve's result, its groups' fresh runs for another grouping of the same mesh, and what its
// log says beyond the result: the rounds solved again, and the share of G_ABD held still.
struct GroupedSolve {
  Result result;
  std::vector<ScheduledRun> fresh;
  std::vector<std::vector<int>> reruns;
  double held_share = 0;
};

// What a solve of the patches in one grouping into solve groups runs from: the topology of the
// groups, the roles of the vertices and the input every group shares (incident faces and the
// average edge length, the same for every grouping of the mesh).
struct GroupedInput {
  GroupedInput(const Problem& problem, const Topology& patch_topo, const std::vector<int>& patch,
               const SolveGroups& groups, const VertexFaces& incident, double ae)
      : solve(groups),
        topo(groups.joins.empty()
                 ? patch_topo
                 : analyse_topology(problem.F, static_cast<int>(problem.V.rows()), groups.group)),
        roles(vertex_roles(problem, topo, problem.params.seams)),
        held_vertices(vertex_roles(problem, topo, SeamMode::Fixed).constrained),
        in{problem.V, problem.F, patch, roles.interior, incident, problem.params, ae} {}
  GroupedInput(const GroupedInput&) = delete;
  GroupedInput& operator=(const GroupedInput&) = delete;

  const SolveGroups& solve;
  const Topology topo;
  const VertexRoles roles;
  const std::vector<char> held_vertices;  // with fixed seams
  const SolveInput in;
};

// Algorithm 1 over the patches of `grouped` (its setup took setup_ms); k_input: K of the input
// per vertex (Eq. 18); earlier: fresh runs of another grouping's solve, or made for this one
// (first_runs), taken where a group would repeat one.
GroupedSolve solve_in_groups(const Problem& problem, const GroupedInput& grouped, double setup_ms,
                             const std::vector<double>& k_input,
                             const std::vector<ScheduledRun>& earlier, const Progress& progress) {
  const auto t0 = Clock::now();
  const Params& params = problem.params;
  const Positions& V = problem.V;
  const Triangles& F = problem.F;
  const SolveInput& in = grouped.in;
  const size_t nf = static_cast<size_t>(F.rows());
  assert(grouped.solve.group.size() == nf);

  Result r;
  r.warnings = warnings(grouped.topo);
  r.average_edge = in.ae;
  r.k_before = k_input;
  r.joins = grouped.solve.joins;
  r.times.setup += setup_ms;  // validation, topology

  SolveSchedule schedule = run_schedule(in, grouped.solve.group, grouped.roles.constrained,
                                        grouped.held_vertices, earlier, progress);
  r.V = schedule.V;
  assert(r.V.rows() == V.rows());  // the output keeps the input's vertex order
  SolveReports reports = patch_reports(schedule, params, nf);
  r.times += reports.times;
  r.factorizations = r.times.factorizations;
  if (reports.unfitted == reports.patches.size()) {
    const std::string& why = reports.first_unfitted_why;
    throw Error(reports.patches.size() == 1
                    ? why
                    : "no patch can be made developable; patch " +
                          std::to_string(reports.first_unfitted) + ": " + why);
  }
  {
    StageTimer timer(r.times.metrics);
    measure_result(r, reports.patches, V, F, in.patch, reports.initial_target, in.interior,
                   grouped.roles.constrained, thread_count(params.threads));
  }
  for (auto& [id, rep] : reports.patches) r.patches.push_back(std::move(rep));
  r.time_ms = setup_ms + ms_since(t0);
  const double held_share =
      held_curvature_share(r.k_before, in.interior, grouped.roles.constrained);
  std::vector<std::vector<int>> reruns = schedule.reruns;
  return {std::move(r), fresh_runs(std::move(schedule)), std::move(reruns), held_share};
}

// Joined seams are kept when they remove at least this much more of G_ABD (percentage points,
// the log's precision): on a tie the seams stay where they are.
constexpr double kJoinMargin = 0.1;

// Progress over [from, to) % of the whole.
Progress part_of(const Progress& progress, int from, int to) {
  if (!progress) return progress;
  return [progress, from, to](int percent, const std::string& stage) {
    progress(from + (to - from) * percent / 100, stage);
  };
}

// Solves the mesh with the seams of `held` held and with those of `joined` joined, and keeps the
// one that removes more G_ABD (r.join_trial gives both figures). Under fixed seams the groups of
// both groupings run at once (first_runs), then each solve takes their runs. setup_ms: of both
// groupings, counted in the first solve.
GroupedSolve join_trial(const Problem& problem, const GroupedInput& held,
                        const GroupedInput& joined, const std::vector<double>& k_input,
                        double setup_ms, const Progress& progress) {
  // The runs made for both solves; their work is counted once, here.
  std::vector<ScheduledRun> runs;
  const bool at_once = problem.params.seams == SeamMode::Fixed;
  StageTimes first_times;
  if (at_once) {
    runs = first_runs({{held.in, held.solve.group, held.held_vertices},
                       {joined.in, joined.solve.group, joined.held_vertices}},
                      part_of(progress, 0, 90));
    for (const ScheduledRun& run : runs) first_times += run.run.outcome.times;
  }
  const Progress held_progress = at_once ? part_of(progress, 90, 95) : part_of(progress, 0, 50);
  GroupedSolve first = solve_in_groups(problem, held, setup_ms, k_input, runs, held_progress);
  // The groups no join changes are not solved again: their runs from the held solve are taken.
  runs.insert(runs.end(), std::make_move_iterator(first.fresh.begin()),
              std::make_move_iterator(first.fresh.end()));
  first.fresh.clear();
  GroupedSolve second =
      solve_in_groups(problem, joined, 0, k_input, runs,
                      at_once ? part_of(progress, 95, 100) : part_of(progress, 50, 100));
  Result& r = first.result;
  Result& j = second.result;
  JoinTrial trial;
  trial.patches = static_cast<int>(
      std::count_if(joined.solve.joins.begin(), joined.solve.joins.end(),
                    [](const PatchJoin& p) { return p.reason == JoinReason::CurvatureOnSeams; }));
  trial.joined = j.abd_reduction;
  trial.held = r.abd_reduction;
  trial.kept_joined = j.abd_reduction >= r.abd_reduction + kJoinMargin;
  if (trial.kept_joined) std::swap(first, second);
  r.times += j.times;  // the whole mesh's stages count the work of both solves, once
  r.times += first_times;
  r.factorizations = r.times.factorizations;
  r.join_trial = trial;
  return first;
}

// Algorithm 1 over the patches the problem gives (the whole mesh as one when it gives none).
// The seams held are those of the solve groups: a patch mostly on seams always joins its
// neighbour; where patches hold most of their curvature on their seams (solve_groups.h), the
// mesh is solved both with them joined and with them held (join_trial, beyond the paper).
// t0: when the caller started (its validation and any segmentation count as setup).
Result approximate_patches(const Problem& problem, const Topology& patch_topo,
                           const Progress& progress, Clock::time_point t0) {
  const Triangles& F = problem.F;
  const size_t nf = static_cast<size_t>(F.rows());
  const std::vector<int> patch = problem.patch.empty() ? std::vector<int>(nf, 0) : problem.patch;
  // The interior vertices do not depend on the solve groups (vertex_roles).
  const std::vector<double> k_input = gaussian_curvature(
      vertex_angles(problem.V, F), vertex_roles(problem, patch_topo, SeamMode::Fixed).interior);
  std::vector<double> curvature(k_input.size());  // |K|, Eq. 18
  std::transform(k_input.begin(), k_input.end(), curvature.begin(),
                 [](double k) { return std::abs(k); });
  const auto [held, joined] = solve_groups(F, patch, patch_topo.boundary, curvature);
  const VertexFaces incident(F, problem.V.rows());
  const double ae = average_edge_length(problem.V, F);
  const GroupedInput held_input(problem, patch_topo, patch, held, incident, ae);
  GroupedSolve solve;
  if (joined.group == held.group) {
    solve = solve_in_groups(problem, held_input, ms_since(t0), k_input, {}, progress);
  } else {
    const GroupedInput joined_input(problem, patch_topo, patch, joined, incident, ae);
    solve = join_trial(problem, held_input, joined_input, k_input, ms_since(t0), progress);
  }
  Result& r = solve.result;
  r.time_ms = ms_since(t0);
  // Made last, so that its total gives the work of every solve the result took.
  r.log = approximate_log(r, solve.reruns, problem.params, solve.held_share);
  if (r.join_trial) r.log.insert(r.log.begin(), join_trial_note(*r.join_trial));
  if (progress) progress(100, "done");
  return std::move(solve.result);
}

}  // namespace

Result approximate(const Problem& problem, const Progress& progress, const SettingText& setting) {
  const auto t0 = Clock::now();
  const Topology topo = validate(problem);
  const SegmentFirstPlan plan = plan_segment_first(problem, topo);
  if (!plan.segment) return approximate_patches(problem, topo, progress, t0);
  Problem split;
  try {
    split = segmented(problem);
  } catch (const Error& e) {
    Result r = approximate_patches(problem, topo, progress, t0);
    r.log.insert(r.log.begin(), std::string("note: the mesh has no patch ids and ") + plan.why +
                                    ", but it could not be split into patches (" + e.what() +
                                    "): solved as one patch");
    return r;
  }
  if (std::all_of(split.patch.begin(), split.patch.end(), [](int id) { return id == 0; })) {
    Result r = approximate_patches(problem, topo, progress, t0);
    r.log.insert(r.log.begin(), "note: the mesh has no patch ids and " + plan.why +
                                    ", but the segmentation keeps it one patch");
    return r;
  }
  Result r = approximate_patches(split, validate(split), progress, t0);
  r.segmented_patch = split.patch;
  const int count = 1 + *std::max_element(split.patch.begin(), split.patch.end());
  r.log.insert(r.log.begin(), segmented_note(plan.why, count, setting));
  return r;
}

}  // namespace qd::approximate
