#include "approximate/solve_schedule.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <thread>

#include "approximate/common_names.h"
#include "approximate/patch_fit.h"
#include "approximate/solve_rounds.h"
#include "common/idle_threads.h"
#include "common/metrics.h"
#include "common/parallel_for.h"
#include "common/serial_libraries.h"
#include "common/thread_count.h"

namespace qd::approximate {
namespace {

struct Pass {
  SolvePass name;
  const std::vector<char>* constrained;  // the vertices no group of the pass moves
  bool per_group;                        // one group per solve group, else one for all
  size_t first = 0, last = 0;            // its groups
};

// G_ABD (Σ|K(v)| over interior vertices, Eq. 18) of the mesh and of each group of a round (over
// the vertices of its faces, seams included): what the never-worse rule keeps from rising when
// groups run at once.
struct RoundFigures {
  double mesh = 0;
  std::vector<double> group;
};
RoundFigures round_figures(const Positions& V, const Triangles& F,
                           const std::vector<char>& interior,
                           const std::vector<std::vector<int>>& groups,
                           const std::vector<size_t>& round) {
  const std::vector<double> K = gaussian_curvature(vertex_angles(V, F), interior);
  RoundFigures out;
  for (double k : K) out.mesh += std::abs(k);
  std::vector<size_t> seen(K.size(), groups.size());  // the last group that counted the vertex
  for (size_t gi : round) {
    double sum = 0;
    for (int f : groups[gi])
      for (int c = 0; c < 3; ++c) {
        const auto v = static_cast<size_t>(F(f, c));
        if (seen[v] != gi) sum += std::abs(K[v]);
        seen[v] = gi;
      }
    out.group.push_back(sum);
  }
  return out;
}

// Worse than before: the mesh's G_ABD, or that of a group that moves a vertex (a group that
// moves none has no step of its own to hold back), rose. Run in turn, groups never make either
// rise: each checks its own faces' vertices, seams included, with its neighbours' results.
bool round_made_worse(const RoundFigures& before, const RoundFigures& after,
                      const std::vector<size_t>& round, const std::vector<ScheduledRun>& runs) {
  if (after.mesh > before.mesh) return true;
  for (size_t k = 0; k < round.size(); ++k) {
    const std::vector<char>& fixed = runs[round[k]].run.group.fixed;
    const bool moves = std::find(fixed.begin(), fixed.end(), 0) != fixed.end();
    if (moves && after.group[k] > before.group[k]) return true;
  }
  return false;
}

// No earlier pass has decided a term for the group's patches: its run depends on its faces,
// their positions and constraints only, none of which another grouping of the other faces
// changes.
bool undecided(const GroupRun& run, const DecidedTerms& decided) {
  return std::none_of(run.fits.begin(), run.fits.end(),
                      [&](const PatchFit& fit) { return decided.count(fit.id) > 0; });
}

// A fresh run of another solve that running `faces` in pass `pass` now would repeat: the same
// faces and vertices held, the same positions to start from and the same input (bitwise: the
// same start, not a close one), nothing decided here either.
const ScheduledRun* repeated_run(const std::vector<ScheduledRun>& earlier, SolvePass pass,
                                 const std::vector<int>& faces,
                                 const std::vector<char>& constrained, const Positions& V,
                                 const Positions& input, const DecidedTerms& decided) {
  for (const ScheduledRun& e : earlier) {
    const GroupMesh& g = e.run.group;
    if (!e.fresh || e.pass != pass || static_cast<size_t>(g.solve_faces) != faces.size() ||
        !std::equal(faces.begin(), faces.end(), g.global_face.begin()))
      continue;
    for (size_t l = 0; l < g.global_vertex.size(); ++l) {
      const auto v = static_cast<Eigen::Index>(g.global_vertex[l]);
      const auto lv = static_cast<Eigen::Index>(l);
      const bool solved = lv < g.solve_vertices;
      if ((solved && g.fixed[l] != constrained[static_cast<size_t>(v)]) ||
          V.row(v) != g.V0.row(lv) || input.row(v) != g.V_input.row(lv))
        return nullptr;
    }
    return undecided(e.run, decided) ? &e : nullptr;
  }
  return nullptr;
}

// Runs run(k, idle) for every group k of `work` (the size of each: its faces, 0 for a group
// that need not run) on up to `threads` threads, the largest first, so that the last to finish
// is a small one; each run depends on its own group only, so the order changes no result.
// idle: the threads no group holds, which a race borrows (idle_threads.h).
template <typename Run>
void run_groups_at_once(const std::vector<size_t>& work, size_t threads, const Run& run) {
  std::vector<size_t> order(work.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return work[a] > work[b]; });
  IdleThreads idle(threads);
  parallel_for(order.size(), std::min(order.size(), threads), [&](size_t i) {
    idle.hold();
    run(order[i], idle);
    idle.release();
  });
}

// What a group run reports as it goes: the share of `total` runs done, `done` of them ended;
// only the caller's thread reports, below 100 % (groups may run again).
std::function<void(double)> runs_progress(const Progress& progress, std::thread::id caller,
                                          const std::atomic<size_t>& done, size_t total) {
  return [&progress, caller, &done, total](double fraction) {
    if (progress && std::this_thread::get_id() == caller)
      progress(std::min(99, static_cast<int>(100.0 * (static_cast<double>(done) + fraction) /
                                             static_cast<double>(total))),
               "deforming");
  };
}

// The groups of a solve group per face, each its faces in order, by group id.
std::vector<std::vector<int>> faces_by_group(const std::vector<int>& group) {
  std::map<int, std::vector<int>> faces_of_group;
  for (size_t f = 0; f < group.size(); ++f) faces_of_group[group[f]].push_back(static_cast<int>(f));
  std::vector<std::vector<int>> out;
  for (auto& [id, faces] : faces_of_group) out.push_back(std::move(faces));
  return out;
}

}  // namespace

bool skips_all_at_once(const Params& params, Eigen::Index vertices) {
  return params.seams == SeamMode::Free && params.developability == Developability::Auto &&
         vertices > kMaxDefectRaceVertices;
}

SolveSchedule run_schedule(const SolveInput& in, const std::vector<int>& group,
                           const std::vector<char>& constrained, const std::vector<char>& held,
                           const std::vector<ScheduledRun>& earlier, const Progress& progress) {
  const Params& params = in.params;
  const Triangles& F = in.F;
  const std::vector<std::vector<int>> faces_of_group = faces_by_group(group);
  std::vector<std::vector<int>> groups;
  std::vector<Pass> passes;
  const auto add_pass = [&](SolvePass name, const std::vector<char>& held_here, bool per_group) {
    passes.push_back({name, &held_here, per_group, groups.size(), 0});
    if (per_group) {
      groups.insert(groups.end(), faces_of_group.begin(), faces_of_group.end());
    } else {
      groups.emplace_back(group.size());
      std::iota(groups.back().begin(), groups.back().end(), 0);
    }
    passes.back().last = groups.size();
  };
  if (params.seams == SeamMode::Free) {
    if (!skips_all_at_once(params, in.input.rows()))
      add_pass(SolvePass::AllAtOnce, constrained, false);
    add_pass(SolvePass::SeamsHeld, held, true);
    add_pass(SolvePass::SeamsFree, constrained, true);
  } else {
    add_pass(SolvePass::Only, held, true);
  }

  // Step 1 and Step 2 per group, pass by pass and round by round (solve_rounds.h): the groups
  // of a round move no common vertex and run in parallel from the positions the earlier
  // rounds left. With a total tolerance each pass moves a vertex only by what the earlier
  // passes left of its budget.
  SolveSchedule out;
  out.V = in.input;
  out.runs.resize(groups.size());
  DecidedTerms decided;  // by the races of the first pass, for the later ones
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<size_t> done{0};
  // The engine's threads run patches, or the two scalar factors of a lone patch's iterative
  // solve: BLAS threads would only contend, and their number would change the rounding, so
  // the result would depend on the threads parameter (serial_libraries.h). Switched once per
  // call, since switching OpenBLAS back and forth restarts its threads.
  const SerialLibraries serial_libraries;
  const size_t threads = thread_count(params.threads);
  const auto run_round = [&](const std::vector<size_t>& round, const Pass& p) {
    for (size_t gi : round) {  // a run about to be replaced: its work was done all the same,
      ScheduledRun& replaced = out.runs[gi];  // and a fresh one is kept for another grouping
      if (!replaced.reused) out.replaced_times += replaced.run.outcome.times;
      if (replaced.fresh) {
        out.replaced.push_back(std::move(replaced));
        replaced = ScheduledRun();
      }
    }
    std::vector<const ScheduledRun*> repeated(round.size());
    for (size_t k = 0; k < round.size(); ++k)
      repeated[k] =
          repeated_run(earlier, p.name, groups[round[k]], *p.constrained, out.V, in.input, decided);
    Params group_params = params;  // a group alone to run in its round has every thread
    group_params.threads =
        static_cast<int>(std::count(repeated.begin(), repeated.end(), nullptr) == 1 ? threads : 1);
    std::vector<size_t> work(round.size());  // a run taken from `earlier` is no work
    for (size_t k = 0; k < round.size(); ++k) work[k] = repeated[k] ? 0 : groups[round[k]].size();
    run_groups_at_once(work, threads, [&](size_t k, IdleThreads& idle) {
      ScheduledRun& here = out.runs[round[k]];
      if (const ScheduledRun* same = repeated[k]) {
        here = *same;
        here.reused = true;
      } else {
        here.run =
            run_group(in, out.V, groups[round[k]], *p.constrained, group_params, decided,
                      p.per_group, idle, runs_progress(progress, caller, done, groups.size()));
        here.pass = p.name;
        here.fresh = undecided(here.run, decided);
        here.reused = false;
      }
      ++done;
    });
  };
  const auto keep = [&](size_t gi) {  // a group's result into out.V
    const GroupRun& run = out.runs[gi].run;
    for (size_t l = 0; l < run.group.global_vertex.size(); ++l)
      if (!run.group.fixed[l])
        out.V.row(run.group.global_vertex[l]) = run.outcome.V.row(static_cast<Eigen::Index>(l));
  };
  for (const Pass& p : passes) {
    const std::vector<std::vector<int>> pass_groups(groups.begin() + static_cast<long>(p.first),
                                                    groups.begin() + static_cast<long>(p.last));
    for (std::vector<size_t> round : solve_rounds(pass_groups, F, *p.constrained)) {
      for (size_t& gi : round) gi += p.first;
      const bool together = round.size() > 1;
      const Positions start = together ? out.V : Positions();
      const RoundFigures before =
          together ? round_figures(out.V, F, in.interior, groups, round) : RoundFigures();
      run_round(round, p);
      for (size_t gi : round) keep(gi);
      if (together && round_made_worse(before, round_figures(out.V, F, in.interior, groups, round),
                                       round, out.runs)) {
        // Never worse (§5.4): each group's step was checked with its neighbours where they
        // started, and together they raised the curvature where they meet. The first group's
        // result stands; the others run again, each from the one before, as they used to.
        std::vector<int> ids;
        for (size_t gi : round)
          for (const PatchFit& fit : out.runs[gi].run.fits) ids.push_back(fit.id);
        out.reruns.push_back(ids);
        out.V = start;
        keep(round.front());
        for (size_t k = 1; k < round.size(); ++k) {
          run_round({round[k]}, p);
          keep(round[k]);
        }
      }
      // The per-patch races of the runs that stand decide for the later passes (a run made
      // again raced again from where its neighbours left it; no group reads another's terms).
      if (p.per_group)
        for (size_t gi : round)
          for (const PatchFit& fit : out.runs[gi].run.fits)
            if (fit.reason == TermReason::Measured) decided[fit.id] = fit.term;
    }
  }
  return out;
}

std::vector<ScheduledRun> first_runs(const std::vector<Grouping>& groupings,
                                     const Progress& progress) {
  struct Job {
    const Grouping& grouping;
    std::vector<int> faces;
  };
  // The same group in two groupings: the same faces, with the same vertices held.
  const auto same = [](const Job& job, const Grouping& g, const std::vector<int>& faces) {
    if (job.faces != faces) return false;
    for (int f : faces)
      for (int c = 0; c < 3; ++c) {
        const auto v = static_cast<size_t>(g.in.F(f, c));
        if (job.grouping.held[v] != g.held[v]) return false;
      }
    return true;
  };
  std::vector<Job> jobs;
  for (const Grouping& g : groupings)
    for (std::vector<int>& faces : faces_by_group(g.group))
      if (std::none_of(jobs.begin(), jobs.end(), [&](const Job& j) { return same(j, g, faces); }))
        jobs.push_back({g, std::move(faces)});
  std::vector<ScheduledRun> out(jobs.size());
  if (jobs.empty()) return out;
  const SerialLibraries serial_libraries;  // as in run_schedule
  const size_t threads = thread_count(groupings.front().in.params.threads);
  Params group_params = groupings.front().in.params;  // a group alone has every thread
  group_params.threads = static_cast<int>(jobs.size() == 1 ? threads : 1);
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<size_t> done{0};
  std::vector<size_t> work;
  for (const Job& job : jobs) work.push_back(job.faces.size());
  run_groups_at_once(work, threads, [&](size_t k, IdleThreads& idle) {
    const SolveInput& in = jobs[k].grouping.in;
    out[k].run = run_group(in, in.input, jobs[k].faces, jobs[k].grouping.held, group_params, {},
                           true, idle, runs_progress(progress, caller, done, jobs.size()));
    out[k].pass = SolvePass::Only;
    out[k].fresh = true;
    ++done;
  });
  return out;
}

std::vector<ScheduledRun> fresh_runs(SolveSchedule&& s) {
  std::vector<ScheduledRun> out = std::move(s.replaced);
  for (ScheduledRun& run : s.runs)
    if (run.fresh) out.push_back(std::move(run));
  return out;
}

}  // namespace qd::approximate
