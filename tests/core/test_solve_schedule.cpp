// A solve in a second grouping of the same mesh (a join trial's, solve_schedule.h) takes the
// runs of the groups the first grouping left unchanged instead of solving them again, and only
// those.
#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "approximate/solve_schedule.h"
#include "approximate/validate.h"
#include "common/mesh.h"
#include "common/topology.h"
#include "test_meshes.h"

namespace qd {
namespace {

using namespace qd::approximate;
using namespace qd::common;

// A grouping of `problem` into the solve groups `group`, with fixed seams, as the engine
// solves it.
struct Grouped {
  Grouped(const Problem& problem, std::vector<int> groups)
      : group(std::move(groups)),
        topo(analyse_topology(problem.F, static_cast<int>(problem.V.rows()), group)),
        roles(vertex_roles(problem, topo, SeamMode::Fixed)),
        incident(problem.F, problem.V.rows()),
        in{problem.V,
           problem.F,
           problem.patch,
           roles.interior,
           incident,
           problem.params,
           average_edge_length(problem.V, problem.F)} {}
  SolveSchedule schedule(const std::vector<ScheduledRun>& earlier) const {
    return run_schedule(in, group, roles.constrained, roles.constrained, earlier, nullptr);
  }
  Grouping grouping() const { return {in, group, roles.constrained}; }

  const std::vector<int> group;
  const Topology topo;
  const VertexRoles roles;
  const VertexFaces incident;
  const SolveInput in;
};

SolveSchedule schedule(const Problem& problem, const std::vector<int>& group,
                       const std::vector<ScheduledRun>& earlier) {
  return Grouped(problem, group).schedule(earlier);
}

// The groups whose first run was taken from `earlier` (some may have run again since).
size_t reused(const SolveSchedule& s) {
  size_t n = 0;
  for (const auto* runs : {&s.runs, &s.replaced})
    n += static_cast<size_t>(
        std::count_if(runs->begin(), runs->end(), [](const ScheduledRun& r) { return r.reused; }));
  return n;
}

TEST(SolveSchedule, ASecondGroupingSolvesOnlyTheGroupsItChanges) {
  Problem p = test::bumpy_cylinder(48, 24, 0.08, 0.0, 6);
  p.params.max_iter = 4;
  p.params.tolerance = 0.2;
  validate(p);
  std::vector<int> joined = p.patch;  // patches 0 and 1 in one group, the others as they were
  for (int& g : joined) g = g == 1 ? 0 : g;

  SolveSchedule first = schedule(p, p.patch, {});
  size_t ran_again = 0;  // groups the never-worse rule ran again: they race again, so are fresh
  for (const std::vector<int>& round : first.reruns) ran_again += round.size() - 1;
  std::vector<ScheduledRun> held = fresh_runs(std::move(first));
  ASSERT_EQ(held.size(), 6u + ran_again);  // each group's first run, from the input, and reruns
  for (const ScheduledRun& r : held) EXPECT_TRUE(r.fresh && !r.reused);

  const SolveSchedule again = schedule(p, joined, held);
  const SolveSchedule alone = schedule(p, joined, {});
  ASSERT_EQ(again.runs.size(), 5u);
  EXPECT_FALSE(again.runs.front().reused);  // patches 0 and 1: a group of its own now
  EXPECT_FALSE(again.reruns.empty());       // the never-worse rule ran some groups again
  EXPECT_EQ(reused(again), 4u);             // patches 2 to 5
  EXPECT_EQ(reused(alone), 0u);
  // Taking a run is solving the group again: the same positions, bit for bit (the engine's
  // solves are deterministic), also where the never-worse rule then runs groups again.
  EXPECT_TRUE((again.V.array() == alone.V.array()).all());
  EXPECT_TRUE((again.V.array() != p.V.array()).any());
}

TEST(SolveSchedule, RunsFromAnotherStartAreNotTaken) {
  Problem p = test::bumpy_cylinder(48, 24, 0.08, 0.0, 6);
  p.params.max_iter = 2;
  validate(p);
  const std::vector<ScheduledRun> first = fresh_runs(schedule(p, p.patch, {}));
  Problem moved = p;  // the same mesh one vertex inside patch 3 apart
  moved.V(12 * 48 + 28, 0) += 1e-9;
  const SolveSchedule second = schedule(moved, moved.patch, first);
  EXPECT_EQ(reused(second), 5u);  // every group but patch 3's
  for (const auto* runs : {&second.runs, &second.replaced})
    for (const ScheduledRun& r : *runs)  // patch 3's start differs, by however little
      EXPECT_FALSE(r.reused && r.run.fits.front().id == 3);
}

// A group the never-worse rule runs again races its terms again from where its neighbours left
// it: its term is that of the run that stands, and so are the candidates it reports (before,
// it took the term its replaced run had raced, and reported no race or an earlier pass's).
TEST(SolveSchedule, AGroupRunAgainRacesAgain) {
  Problem p = test::bumpy_cylinder(48, 24, 0.08, 0.0, 6);
  p.params.max_iter = 4;
  p.params.tolerance = 0.2;
  validate(p);
  const SolveSchedule s = schedule(p, p.patch, {});
  ASSERT_FALSE(s.reruns.empty());
  size_t checked = 0;
  for (const std::vector<int>& round : s.reruns)
    for (size_t k = 1; k < round.size(); ++k)  // the first group's result stands
      for (const ScheduledRun& r : s.runs) {
        const PatchFit& fit = r.run.fits.front();
        if (fit.id != round[k] || fit.reason != TermReason::Measured) continue;
        ASSERT_FALSE(r.run.race.empty()) << "patch " << fit.id;
        const auto kept = std::find_if(r.run.race.begin(), r.run.race.end(),
                                       [](const CandidateFigures& c) { return c.kept; });
        ASSERT_NE(kept, r.run.race.end()) << "patch " << fit.id;
        EXPECT_EQ(kept->term, fit.term) << "patch " << fit.id;
        ++checked;
      }
  EXPECT_GT(checked, 0u);
}

// Both groupings of a join trial are solved from runs made at once, each group two groupings
// share made once: each solve then takes every group of its one pass from them, and ends
// where solving it alone ends, bit for bit, never-worse re-runs included. The work of the runs
// those re-runs replace is counted.
TEST(SolveSchedule, TwoGroupingsRunTheirGroupsOnceAndAtOnce) {
  Problem p = test::bumpy_cylinder(48, 24, 0.08, 0.0, 6);
  p.params.max_iter = 4;
  p.params.tolerance = 0.2;
  validate(p);
  std::vector<int> joined_groups = p.patch;  // patches 0 and 1 in one group
  for (int& g : joined_groups) g = g == 1 ? 0 : g;
  const Grouped held(p, p.patch), joined(p, joined_groups);

  const std::vector<ScheduledRun> runs = first_runs({held.grouping(), joined.grouping()}, nullptr);
  EXPECT_EQ(runs.size(), 7u);  // 6 held groups and the joined one; patches 2 to 5 once
  for (const ScheduledRun& r : runs) EXPECT_TRUE(r.fresh && !r.reused);
  size_t reruns = 0;
  for (const Grouped* g : {&held, &joined}) {
    const SolveSchedule taken = g->schedule(runs), alone = g->schedule({});
    EXPECT_EQ(reused(taken), taken.runs.size());  // every group's first run
    EXPECT_TRUE((taken.V.array() == alone.V.array()).all());
    EXPECT_EQ(taken.reruns.size(), alone.reruns.size());
    reruns += alone.reruns.size();
    // The work of a replaced run counts with the solve that made it: here, or where it was taken.
    EXPECT_EQ(alone.replaced_times.factorizations > 0, !alone.reruns.empty());
    EXPECT_EQ(taken.replaced_times.factorizations, 0);
  }
  EXPECT_GT(reruns, 0u);  // the never-worse rule ran some groups again
}

}  // namespace
}  // namespace qd
