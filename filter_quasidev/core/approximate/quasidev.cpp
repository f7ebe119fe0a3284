// Algorithm 1 of the paper over a whole mesh: validation, solve groups (one per patch; free seams
// in three passes, see approximate()), Step 1 per patch, Step 2 per group, reports.
#include "approximate/quasidev.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numeric>
#include <thread>
#include <unordered_set>

#include "approximate/approximate_log.h"
#include "approximate/deformer.h"
#include "approximate/patch_fit.h"
#include "approximate/segment_first.h"
#include "approximate/solve_groups.h"
#include "approximate/term_race.h"
#include "approximate/group_mesh.h"
#include "approximate/solve_rounds.h"
#include "approximate/target_normals.h"
#include "approximate/validate.h"
#include "common/error.h"
#include "common/metrics.h"
#include "common/parallel_for.h"
#include "common/serial_libraries.h"
#include "common/stage_timer.h"
#include "common/topology.h"

namespace qd {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

std::vector<int> indices(size_t n) {
  std::vector<int> v(n);
  std::iota(v.begin(), v.end(), 0);
  return v;
}

// Step 1 and Step 2 of one solve group, from the input positions.
struct GroupRun {
  GroupMesh group;
  std::vector<PatchFit> fits;
  std::vector<Vec3> targets;  // initial target per group face
  DeformOutcome outcome;
  std::vector<CandidateFigures> race;  // Developability::Auto's candidates, if it raced
  double initial_g = 0;                // the group's G_ABD when it started
  double time_ms = 0;
};

// With a total tolerance, what each vertex has left of its budget after the moves of earlier
// groups (input: the positions before any): |v' − v_now| ≤ δ − |v_now − v_input| keeps
// |v' − v_input| ≤ δ.
void spend_earlier_moves(GroupMesh& g, const Positions& input) {
  for (size_t l = 0; l < g.global_vertex.size(); ++l) {
    const double moved = (g.V0.row(static_cast<Eigen::Index>(l)) - input.row(g.global_vertex[l])).norm();
    g.tolerance[l] = std::max(0.0, g.tolerance[l] - moved);
  }
}

// The terms decided for each patch id by an earlier pass's race (Developability::Auto).
using DecidedTerms = std::map<int, Term>;

// The fits with `term` on every patch the race decides (a patch no curve fits takes the
// defect rows instead of the curve targets).
std::vector<PatchFit> with_term(std::vector<PatchFit> fits, Term term) {
  for (PatchFit& p : fits)
    if (p.reason == TermReason::Measured) p.term = p.fitted() || term == Term::Defect ? term : Term::Defect;
  return fits;
}

GroupRun run_group(const Positions& input, const Positions& V, const Triangles& F,
                   const std::vector<int>& faces, const std::vector<int>& patch,
                   const std::vector<char>& constrained, const std::vector<char>& interior,
                   const VertexFaces& incident, const Params& params, double ae,
                   const DecidedTerms& decided, bool one_unit,
                   const std::function<void(double)>& progress) {
  const auto t0 = Clock::now();
  GroupRun run;
  double setup_ms = 0;
  {
    StageTimer timer(setup_ms);
    run.group = extract_group(V, F, faces, patch, constrained, interior, incident, params);
    for (size_t l = 0; l < run.group.global_vertex.size(); ++l)
      run.group.V_input.row(static_cast<Eigen::Index>(l)) = input.row(run.group.global_vertex[l]);
    if (one_unit) std::fill(run.group.face_unit.begin(), run.group.face_unit.end(), run.group.face_patch.front());
    if (params.tolerance_mode == ToleranceMode::Total) spend_earlier_moves(run.group, input);
  }
  const GroupMesh& g = run.group;
  const size_t threads = static_cast<size_t>(params.threads);
  double step1_ms = 0;
  std::vector<Term> candidates;  // of the race, when a patch's term is to be measured
  {
    StageTimer timer(step1_ms);
    run.fits = fit_patches(g, g.V0, threads);
    for (PatchFit& p : run.fits) {
      choose_term(p, params.developability);
      const auto given = decided.find(p.id);
      if (p.reason != TermReason::Measured) continue;
      if (given != decided.end()) {
        p.term = given->second;
        p.reason = TermReason::Given;
      } else if (candidates.size() < 2) {
        candidates = candidate_terms(p, g.solve_vertices);
      }
    }
    if (candidates.size() == 1) run.fits = with_term(run.fits, candidates.front());
    run.targets = group_targets(g, run.fits);
  }
  bool all_idle = candidates.size() < 2;
  for (const PatchFit& p : run.fits) all_idle = all_idle && p.idle();
  if (all_idle) {
    run.outcome.V = g.V0;
    run.outcome.stop = StopReason::NothingToDo;
    run.outcome.stop_detail = run.fits.front().skipped.empty()
                                  ? "planar: the Gauss image is a point, nothing to do"
                                  : "left unchanged: " + run.fits.front().skipped;
  } else if (candidates.size() > 1) {
    // Each candidate's fits outlive its run: the re-projection keeps a reference to them.
    std::map<Term, std::vector<PatchFit>> fits_of;
    for (Term t : candidates) fits_of[t] = with_term(run.fits, t);
    const auto start = [&](Term t) {
      const std::vector<PatchFit>& fits = fits_of.at(t);
      return Deformation(g, group_targets(g, fits), make_retarget(g, fits, params.targets, threads),
                         group_defect_rows(g, fits), params, ae);
    };
    RaceOutcome race = race_terms(candidates, start, params.max_iter, params.stop_abd / 100, progress);
    run.fits = fits_of.at(race.winner);
    run.targets = group_targets(g, run.fits);
    run.outcome = std::move(race.outcome);
    run.race = std::move(race.candidates);
    run.initial_g = race.initial_g;
  } else {
    run.outcome = deform(g, run.targets, make_retarget(g, run.fits, params.targets, threads),
                         group_defect_rows(g, run.fits), params, ae, progress);
  }
  run.outcome.times.setup += setup_ms;
  run.outcome.times.step1 += step1_ms;
  run.time_ms = ms_since(t0);
  return run;
}

// G_ABD (Σ|K(v)| over interior vertices, Eq. 18) of the mesh and of each group of a round (over
// the vertices of its faces, seams included): what the never-worse rule keeps from rising when
// groups run at once.
struct RoundFigures {
  double mesh = 0;
  std::vector<double> group;
};
RoundFigures round_figures(const Positions& V, const Triangles& F, const std::vector<char>& interior,
                           const std::vector<std::vector<int>>& groups, const std::vector<size_t>& round) {
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
bool round_made_worse(const RoundFigures& before, const RoundFigures& after, const std::vector<size_t>& round,
                      const std::vector<GroupRun>& runs) {
  if (after.mesh > before.mesh) return true;
  for (size_t k = 0; k < round.size(); ++k) {
    const std::vector<char>& fixed = runs[round[k]].group.fixed;
    const bool moves = std::find(fixed.begin(), fixed.end(), 0) != fixed.end();
    if (moves && after.group[k] > before.group[k]) return true;
  }
  return false;
}

std::string round_rerun_note(const std::vector<size_t>& round, const std::vector<GroupRun>& runs) {
  std::string ids;
  for (size_t gi : round)
    for (const PatchFit& p : runs[gi].fits) ids += (ids.empty() ? "" : ", ") + std::to_string(p.id);
  return "note: patches " + ids +
         ", solved at once, raised the curvature where they meet; solved again one after the other";
}

// Threads to use: the parameter, or every core when it is 0.
size_t thread_count(int requested) {
  if (requested > 0) return static_cast<size_t>(requested);
  return std::max(1u, std::thread::hardware_concurrency());
}

// Algorithm 1 over the patches the problem gives (the whole mesh as one when it gives none).
// "note: patch 12 (8 faces) ..." for each patch solved in another's group (solve_groups.h).
std::vector<std::string> merge_notes(const SolveGroups& groups) {
  std::vector<std::string> notes;
  for (const PatchMerge& m : groups.merged)
    notes.push_back("note: patch " + std::to_string(m.patch) + " (" + std::to_string(m.faces) +
                    (m.faces == 1 ? " face" : " faces") +
                    ") has most of its vertices on seams or the boundary: it is solved together "
                    "with patch " + std::to_string(m.group) + ", and the seam between them moves");
  return notes;
}

Result approximate_patches(const Problem& problem, const Topology& patch_topo, const Progress& progress) {
  const auto t0 = Clock::now();
  const Params& params = problem.params;
  const Positions& V = problem.V;
  const Triangles& F = problem.F;
  const size_t nv = static_cast<size_t>(V.rows()), nf = static_cast<size_t>(F.rows());
  const std::vector<int> patch = problem.patch.empty() ? std::vector<int>(nf, 0) : problem.patch;
  // The seams held and the patches too small to fit are those of the solve groups.
  const SolveGroups solve = solve_groups(F, patch, patch_topo.boundary, params.seams == SeamMode::Free);
  const Topology topo = solve.merged.empty()
                            ? patch_topo
                            : analyse_topology(F, static_cast<int>(nv), solve.group);
  const VertexRoles roles = vertex_roles(problem, topo, params.seams);
  const std::vector<char>& interior = roles.interior;
  const std::vector<char>& constrained = roles.constrained;
  const std::vector<char> held = vertex_roles(problem, topo, SeamMode::Fixed).constrained;
  const VertexFaces incident(F, V.rows());

  Result r;
  r.V = V;
  r.warnings = warnings(topo);
  for (const std::string& w : r.warnings) r.log.push_back("warning: " + w);
  for (const std::string& note : merge_notes(solve)) r.log.push_back(note);
  r.average_edge = average_edge_length(V, F);
  const VertexAngles angles_before = vertex_angles(V, F);
  r.k_before = gaussian_curvature(angles_before, interior);
  r.times.setup += ms_since(t0);  // validation, topology, the input's figures

  std::map<int, std::vector<int>> faces_of_patch, faces_of_group;
  for (size_t f = 0; f < nf; ++f) {
    faces_of_patch[patch[f]].push_back(static_cast<int>(f));
    faces_of_group[solve.group[f]].push_back(static_cast<int>(f));
  }
  // One group per patch, its seams held (the paper). Free seams take three passes, each
  // starting where the one before ended, so none can undo another (never-worse rule): all
  // patches in one group (its one step scale is set by the worst patch, so it stalls early on
  // draped garments; Developability::Auto races one term for all its patches), then each patch
  // with its seams held (where Auto measures each patch's own term, which the last pass
  // keeps), then each patch again moving its seam vertices (moved by one patch, seen by the
  // next, so they stay shared). Measured on the shared garments, free seams then remove more
  // than fixed ones (issue 11). With a total tolerance each pass moves a vertex only by what
  // the earlier passes left of its budget. Patches are solved in solve groups (solve_groups.h).
  struct Pass {
    const char* name;                      // in the reports when there are several
    const std::vector<char>* constrained;  // the vertices no group of the pass moves
    bool per_group;                        // one group per solve group (solve_groups.h)
    size_t first = 0, last = 0;            // its groups
  };
  std::vector<std::vector<int>> groups;
  std::vector<Pass> passes;
  const auto add_pass = [&](const char* name, const std::vector<char>& held_here, bool per_patch) {
    passes.push_back({name, &held_here, per_patch, groups.size(), 0});
    if (per_patch)
      for (auto& [id, faces] : faces_of_group) groups.push_back(faces);
    else
      groups.push_back(indices(nf));
    passes.back().last = groups.size();
  };
  const auto pass_of = [&](size_t gi) -> const Pass& {
    return *std::find_if(passes.begin(), passes.end(), [gi](const Pass& p) { return gi < p.last; });
  };
  const bool free_seams = params.seams == SeamMode::Free;
  if (free_seams) add_pass("all patches at once", constrained, false);
  add_pass("seams held", held, true);
  if (free_seams) add_pass("seams free", constrained, true);

  // Step 1 and Step 2 per group, pass by pass and round by round (solve_rounds.h): the groups
  // of a round move no common vertex and run in parallel from the positions the earlier
  // rounds left.
  std::vector<GroupRun> runs(groups.size());
  DecidedTerms decided;  // by the races of the first pass, for the later ones
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<size_t> done{0};
  // The engine's threads run patches, or the two scalar factors of a lone patch's iterative
  // solve: BLAS threads would only contend, and their number would change the rounding, so
  // the result would depend on --threads (serial_libraries.h). Switched once per call, since switching OpenBLAS
  // back and forth restarts its threads.
  const SerialLibraries serial_libraries;
  const auto run_round = [&](const std::vector<size_t>& round, const Pass& p) {
    Params group_params = params;  // a patch alone in its round has every thread
    group_params.threads = static_cast<int>(round.size() == 1 ? thread_count(params.threads) : 1);
    parallel_for(round.size(), std::min(round.size(), thread_count(params.threads)), [&](size_t k) {
      // Only the caller's thread reports; below 100 % even when groups run again (rare).
      const auto group_progress = [&](double fraction) {
        if (progress && std::this_thread::get_id() == caller)
          progress(std::min(99, static_cast<int>(100.0 * (static_cast<double>(done) + fraction) /
                                                 static_cast<double>(groups.size()))),
                   "deforming");
      };
      runs[round[k]] = run_group(V, r.V, F, groups[round[k]], patch, *p.constrained, interior,
                                 incident, group_params, r.average_edge, decided, p.per_group,
                                 group_progress);
      ++done;
    });
    if (p.per_group)  // the per-patch races decide for the later passes
      for (size_t gi : round)
        for (const PatchFit& fit : runs[gi].fits)
          if (fit.reason == TermReason::Measured) decided[fit.id] = fit.term;
  };
  const auto keep = [&](size_t gi) {  // a group's result into r.V
    const GroupRun& run = runs[gi];
    for (size_t l = 0; l < run.group.global_vertex.size(); ++l)
      if (!run.group.fixed[l])
        r.V.row(run.group.global_vertex[l]) = run.outcome.V.row(static_cast<Eigen::Index>(l));
  };
  for (const Pass& p : passes) {
    const std::vector<std::vector<int>> pass_groups(groups.begin() + static_cast<long>(p.first),
                                                    groups.begin() + static_cast<long>(p.last));
    for (std::vector<size_t> round : solve_rounds(pass_groups, F, *p.constrained)) {
      for (size_t& gi : round) gi += p.first;
      const bool together = round.size() > 1;
      const Positions start = together ? r.V : Positions();
      const RoundFigures before = together ? round_figures(r.V, F, interior, groups, round) : RoundFigures();
      run_round(round, p);
      for (size_t gi : round) keep(gi);
      if (!together || !round_made_worse(before, round_figures(r.V, F, interior, groups, round), round, runs))
        continue;
      // Never worse (§5.4): each group's step was checked with its neighbours where they
      // started, and together they raised the curvature where they meet. The first group's
      // result stands; the others run again, each from the one before, as they used to.
      r.log.push_back(round_rerun_note(round, runs));
      r.V = start;
      keep(round.front());
      for (size_t k = 1; k < round.size(); ++k) {
        run_round({round[k]}, p);
        keep(round[k]);
      }
    }
  }

  std::vector<Vec3> initial_target(nf);
  size_t skipped_patches = 0;
  std::string first_skip;  // the reason of the first patch Step 1 could not fit
  std::map<int, PatchReport> reports;
  for (size_t gi = 0; gi < runs.size(); ++gi) {
    const GroupRun& run = runs[gi];
    r.times += run.outcome.times;
    for (size_t f = 0; f < run.targets.size(); ++f)
      initial_target[static_cast<size_t>(run.group.global_face[f])] = run.targets[f];
    for (const PatchFit& p : run.fits) {
      PatchReport& rep = reports[p.id];
      rep.id = p.id;
      rep.target_kind = p.fit.model->kind();
      rep.fit_residual_deg = p.fit.residual_deg;
      rep.tolerance = patch_tolerance(params, p.id);
      const bool first = rep.stop_reason.empty();
      rep.iterations += static_cast<int>(run.outcome.history.size());
      rep.iterations_run += run.outcome.iterations_run;
      rep.developability = term_name(p.term);
      if (!run.race.empty()) rep.candidates = candidate_reports(run.race, run.initial_g);
      if (first || !run.race.empty()) rep.developability_reason = term_reason_text(p, rep.candidates);
      const bool unfitted = p.idle() && !p.skipped.empty();
      std::string stop = unfitted ? "left unchanged: " + p.skipped : stop_text(run.outcome, params);
      if (free_seams) stop = pass_of(gi).name + (": " + stop);
      rep.stop_reason = first ? stop : rep.stop_reason + "; then " + stop;
      if (unfitted && first && skipped_patches++ == 0) first_skip = "patch " + std::to_string(p.id) + ": " + p.skipped;
      rep.history.insert(rep.history.end(), run.outcome.history.begin(), run.outcome.history.end());
      rep.time_ms += run.time_ms / static_cast<double>(run.fits.size());
    }
  }
  r.factorizations = r.times.factorizations;

  if (skipped_patches == faces_of_patch.size())
    throw Error(faces_of_patch.size() == 1 ? first_skip.substr(first_skip.find(": ") + 2)
                                           : "no patch can be made developable; " + first_skip);

  {  // the reports' figures, from the angles of every vertex before and after
    StageTimer timer(r.times.metrics);
    const VertexAngles angles_after = vertex_angles(r.V, F);
    // Per-patch figures: each patch measured on its own faces, vertices and interior vertices
    // (the curvature of a seam vertex counts in every patch it touches).
    std::vector<int> ids;
    for (const auto& entry : faces_of_patch) ids.push_back(entry.first);
    parallel_for(ids.size(), thread_count(params.threads), [&](size_t k) {
      const int id = ids[k];
      const std::vector<int>& faces = faces_of_patch.at(id);
      std::vector<int> vertices, owned;  // in the order the faces reach them
      std::unordered_set<int> seen;       // not a flag per mesh vertex: patches × vertices
      seen.reserve(3 * faces.size());
      for (int f : faces)
        for (int c = 0; c < 3; ++c) {
          const auto v = static_cast<size_t>(F(f, c));
          if (!seen.insert(static_cast<int>(v)).second) continue;
          vertices.push_back(static_cast<int>(v));
          if (interior[v]) owned.push_back(static_cast<int>(v));
        }
      std::vector<Vec3> t;
      for (int f : faces) t.push_back(initial_target[static_cast<size_t>(f)]);
      PatchReport& rep = reports.at(id);  // the map is not resized here: safe in parallel
      rep.faces = static_cast<int>(faces.size());
      rep.vertices = static_cast<int>(vertices.size());
      rep.free_vertices = static_cast<int>(std::count_if(
          vertices.begin(), vertices.end(), [&](int v) { return !constrained[static_cast<size_t>(v)]; }));
      rep.before = measure(angles_before, V, V, F, owned, faces, t, vertices);
      rep.after = measure(angles_after, V, r.V, F, owned, faces, t, vertices);
      rep.abd_reduction = rep.before.g_abd > 0
                              ? 100.0 * (rep.before.g_abd - rep.after.g_abd) / rep.before.g_abd
                              : 0.0;
      rep.obd_reduction =
          rep.before.obd > 0 ? 100.0 * (rep.before.obd - rep.after.obd) / rep.before.obd : 0.0;
    });
    for (const auto& [id, rep] : reports) {
      r.patches.push_back(rep);
      r.log.push_back(patch_log_line(rep, r.average_edge));
    }

    std::vector<int> interior_list;
    for (size_t v = 0; v < nv; ++v)
      if (interior[v]) interior_list.push_back(static_cast<int>(v));
    const std::vector<int> all_faces = indices(nf), all_vertices = indices(nv);
    r.k_after = gaussian_curvature(angles_after, interior);
    r.displacement.resize(nv);
    for (size_t v = 0; v < nv; ++v)
      r.displacement[v] = (r.V.row(static_cast<Eigen::Index>(v)) - V.row(static_cast<Eigen::Index>(v))).norm();
    r.total_before = measure(angles_before, V, V, F, interior_list, all_faces, initial_target, all_vertices);
    r.total_after = measure(angles_after, V, r.V, F, interior_list, all_faces, initial_target, all_vertices);
    r.abd_reduction = r.total_before.g_abd > 0 ? 100.0 * (r.total_before.g_abd - r.total_after.g_abd) /
                                                     r.total_before.g_abd
                                               : 0.0;
  }
  double on_held = 0, all = 0;  // the input's |K| on interior vertices, and on those held
  for (size_t v = 0; v < nv; ++v) {
    all += std::abs(r.k_before[v]);
    if (interior[v] && constrained[v]) on_held += std::abs(r.k_before[v]);
  }
  r.time_ms = ms_since(t0);
  r.log.push_back(total_log_line(r));
  for (const std::string& line : advice(r, params, all > 0 ? 100.0 * on_held / all : 0.0))
    r.log.push_back("note: " + line);
  if (progress) progress(100, "done");
  return r;
}

}  // namespace

Result approximate(const Problem& problem, const Progress& progress) {
  const auto t0 = Clock::now();
  const Topology topo = validate(problem);
  const SegmentFirstPlan plan = plan_segment_first(problem, topo);
  if (!plan.segment) return approximate_patches(problem, topo, progress);
  Problem split;
  try {
    split = segmented(problem);
  } catch (const Error& e) {
    Result r = approximate_patches(problem, topo, progress);
    r.log.insert(r.log.begin(), std::string("note: the mesh has no patch ids and ") + plan.why +
                                    ", but it could not be split into patches (" + e.what() +
                                    "): solved as one patch");
    return r;
  }
  if (std::all_of(split.patch.begin(), split.patch.end(), [](int id) { return id == 0; })) {
    Result r = approximate_patches(problem, topo, progress);
    r.log.insert(r.log.begin(), "note: the mesh has no patch ids and " + plan.why +
                                    ", but the segmentation keeps it one patch");
    return r;
  }
  const double split_ms = ms_since(t0);
  Result r = approximate_patches(split, validate(split), progress);
  r.segmented_patch = split.patch;
  const int count = 1 + *std::max_element(split.patch.begin(), split.patch.end());
  r.log.insert(r.log.begin(),
               "note: the mesh has no patch ids and " + plan.why + ": split into " +
                   std::to_string(count) + " nearly developable patches (segment, largest fit error " +
                   std::to_string(static_cast<int>(kSegmentFirstMaxErrorDeg)) +
                   "°), solved with free seams (segment-first set to never keeps it one patch)");
  r.times.setup += split_ms;
  r.time_ms += split_ms;
  return r;
}

}  // namespace qd
