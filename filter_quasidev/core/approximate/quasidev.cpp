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

#include "approximate/deformer.h"
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

// Below this fit residual a planar patch is already developable: nothing to do.
constexpr double kPlanarResidualDeg = 0.05;
// Above this fit residual the patch is far from one developable surface: warn.
constexpr double kFarResidualDeg = 10.0;

// The model of a patch Step 1 could not fit (e.g. its normals fill the sphere): every face
// keeps its own normal as target, so the patch keeps its shape.
class KeepNormals : public GaussModel {
 public:
  Vec3 project(const Vec3& n, int&) const override { return n; }
  std::string kind() const override { return "unchanged"; }
};

// Developability::Auto takes the paper's curve targets up to this fit residual and the
// angle-defect rows above it (a Gauss image that is a 2-D blob, not a curve; measured on the
// shared garments and samples, README "Garments").
constexpr double kAutoDefectResidualDeg = 5.0;

// The developability rows a patch gets.
enum class Term { None, Curve, Defect, Both };

const char* term_name(Term t) {
  return t == Term::Curve ? "curve" : t == Term::Defect ? "defect" : t == Term::Both ? "both" : "none";
}

// Step 1 for one patch of a group: its faces (local indices), the fitted Gauss model, and the
// developability term chosen for it.
struct PatchFit {
  int id = 0;
  std::vector<int> faces;
  TargetFit fit;
  std::string skipped;  // why Step 1 failed; empty when it succeeded
  Term term = Term::None;
  std::string why;      // why this term (the log and the report say it)
  bool planar() const {
    return fit.model->kind() == "plane" && fit.residual_deg < kPlanarResidualDeg;
  }
  bool idle() const { return term == Term::None; }
  bool has_targets() const { return term == Term::Curve || term == Term::Both; }
  bool has_defects() const { return term == Term::Defect || term == Term::Both; }
};

std::string format(const char* fmt, double a, double b = 0, double c = 0, double d = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b, c, d);
  return buf;
}

// "G_ABD a → b (−r%), " with the sign of the change: a rise reads "(+r%)".
std::string g_abd_change(const Figures& before, const Figures& after, double reduction) {
  return format(reduction >= 0 ? "G_ABD %.4g → %.4g (−%.1f%%), " : "G_ABD %.4g → %.4g (+%.1f%%), ",
                before.g_abd, after.g_abd, std::abs(reduction));
}

// The term of a patch from the parameter and its Step 1 fit. Curve is the paper; the angle
// defects need no fit, so they also take patches whose normals fill the sphere.
void choose_term(PatchFit& p, Developability mode) {
  if (p.planar() || p.faces.size() < static_cast<size_t>(kMinPatchFaces)) {
    p.why = p.planar() ? "planar" : "too small";
    return;
  }
  const bool fitted = p.skipped.empty();
  switch (mode) {
    case Developability::Curve:
      p.term = fitted ? Term::Curve : Term::None;
      p.why = "as asked";
      return;
    case Developability::Defect:
      p.term = Term::Defect;
      p.why = "as asked";
      return;
    case Developability::Both:
      p.term = fitted ? Term::Both : Term::Defect;
      p.why = fitted ? "as asked" : "no Gauss-image curve fits";
      return;
    case Developability::Auto:
      if (!fitted) {
        p.term = Term::Defect;
        p.why = "auto: no Gauss-image curve fits";
      } else if (p.fit.residual_deg > kAutoDefectResidualDeg) {
        p.term = Term::Defect;
        p.why = format("auto: fit residual %.1f° > %.0f°, the Gauss image is not a curve",
                       p.fit.residual_deg, kAutoDefectResidualDeg);
      } else {
        p.term = Term::Curve;
        p.why = format("auto: fit residual %.1f° <= %.0f°", p.fit.residual_deg,
                       kAutoDefectResidualDeg);
      }
      return;
  }
}

void normals_and_areas(const Positions& X, const Triangles& F, const std::vector<int>& faces,
                       std::vector<Vec3>& normals, std::vector<double>& areas) {
  normals.clear();
  areas.clear();
  for (int f : faces) {
    normals.push_back(face_normal(X, F, f));
    areas.push_back(face_area(X, F, f));
  }
}

// Step 1 for one patch (its projections on up to `threads` threads). A patch too small to fit
// (validate() let it through, its vertices fixed) or one Step 1 cannot fit keeps its own
// normals as targets.
PatchFit fit_patch(int id, const std::vector<int>& faces, const std::vector<Vec3>& normals,
                   const std::vector<double>& areas, size_t threads) {
  PatchFit p;
  p.id = id;
  p.faces = faces;
  if (faces.size() < static_cast<size_t>(kMinPatchFaces)) {
    p.skipped = "fewer than " + std::to_string(kMinPatchFaces) + " faces, too few to fit";
  } else {
    try {
      p.fit = fit_targets(normals, areas, threads);
      return p;
    } catch (const Error& e) {
      p.skipped = e.what();
    }
  }
  p.fit.model = std::make_shared<KeepNormals>();
  p.fit.targets = normals;
  return p;
}

std::vector<PatchFit> fit_patches(const GroupMesh& g, const Positions& X, size_t threads) {
  std::map<int, std::vector<int>> faces_of;
  for (Eigen::Index f = 0; f < g.solve_faces; ++f)
    faces_of[g.face_patch[static_cast<size_t>(f)]].push_back(static_cast<int>(f));
  std::vector<PatchFit> fits;
  std::vector<Vec3> normals;
  std::vector<double> areas;
  for (auto& [id, faces] : faces_of) {
    normals_and_areas(X, g.F, faces, normals, areas);
    fits.push_back(fit_patch(id, faces, normals, areas, threads));
  }
  return fits;
}

// Target per group face from the per-patch fits; zero (no Eq. 13 developability rows) on the
// faces of patches that take the angle-defect rows only.
std::vector<Vec3> group_targets(const GroupMesh& g, const std::vector<PatchFit>& fits) {
  std::vector<Vec3> t(static_cast<size_t>(g.solve_faces), Vec3::Zero());
  for (const PatchFit& p : fits)
    if (p.term != Term::Defect)
      for (size_t k = 0; k < p.faces.size(); ++k) t[static_cast<size_t>(p.faces[k])] = p.fit.targets[k];
  return t;
}

// Re-projection (nearest point of the fixed c_3D) or re-fit (Step 1 again, each patch keeping
// its term) between iterations, on up to `threads` threads.
Retarget make_retarget(const GroupMesh& g, const std::vector<PatchFit>& fits, TargetMode mode,
                       size_t threads) {
  return [&g, &fits, mode, threads](const Positions& X) {
    if (mode == TargetMode::Refit) {
      std::vector<PatchFit> refits = fit_patches(g, X, threads);
      for (size_t k = 0; k < refits.size(); ++k) refits[k].term = fits[k].term;
      return group_targets(g, refits);
    }
    std::vector<Vec3> t(static_cast<size_t>(g.solve_faces), Vec3::Zero());
    std::vector<Vec3> normals;
    for (const PatchFit& p : fits) {
      if (p.term == Term::Defect) continue;
      normals.clear();
      for (int f : p.faces) normals.push_back(face_normal(X, g.F, f));
      const std::vector<Vec3> targets = project_normals(*p.fit.model, normals, threads);
      for (size_t k = 0; k < p.faces.size(); ++k) t[static_cast<size_t>(p.faces[k])] = targets[k];
    }
    return t;
  };
}

// Per local vertex, 1 = an angle-defect row: the free interior vertices that touch a face of
// a defect patch (empty when there is none).
std::vector<char> group_defect_rows(const GroupMesh& g, const std::vector<PatchFit>& fits) {
  std::vector<char> has_row(g.fixed.size(), 0);
  for (const PatchFit& p : fits)
    if (p.has_defects())
      for (int f : p.faces)
        for (int c = 0; c < 3; ++c) has_row[static_cast<size_t>(g.F(f, c))] = 1;
  std::vector<char> interior(g.fixed.size(), 0);
  for (int v : g.owned) interior[static_cast<size_t>(v)] = 1;
  bool any = false;
  for (size_t v = 0; v < has_row.size(); ++v) {
    has_row[v] = has_row[v] && interior[v] && !g.fixed[v];
    any = any || has_row[v];
  }
  if (!any) return {};
  return has_row;
}

std::vector<int> indices(size_t n) {
  std::vector<int> v(n);
  std::iota(v.begin(), v.end(), 0);
  return v;
}

// One log line per patch (what adapters show): its size, Step 1 fit, iterations and why they
// stopped, G_ABD before → after, the last iteration's ratios (Eqs. 19–20), displacement, time.
std::string patch_log_line(const PatchReport& p, double ae) {
  if (p.developability == "none" && p.target_kind == "unchanged")
    return "patch " + std::to_string(p.id) + ": " + std::to_string(p.faces) + " faces, " +
           p.stop_reason;
  const IterationReport last = p.history.empty() ? IterationReport{} : p.history.back();
  const std::string fit = p.target_kind == "unchanged"
                              ? "no curve fit"
                              : p.target_kind + format(" fit residual %.2f°", p.fit_residual_deg);
  std::string s = "patch " + std::to_string(p.id) + ": " + std::to_string(p.faces) + " faces, " +
                  fit + ", developability " + p.developability + " (" + p.developability_reason +
                  "), " +
                  std::to_string(p.iterations) + " iteration(s) (stop: " + p.stop_reason + "), " +
                  g_abd_change(p.before, p.after, p.abd_reduction) +
                  format("last ratio_ABD %.1f%%, ratio_OBD %.1f%%, ", last.ratio_abd,
                         last.ratio_obd) +
                  format("max displacement %.3g AE, %.0f ms", p.after.max_disp / ae, p.time_ms);
  if (p.developability == "curve" && p.fit_residual_deg > kFarResidualDeg)
    s += format(
        "; warning: fit residual %.1f°: this patch is far from one developable surface, which "
        "the paper's method assumes: use --developability defect or auto, or split it into "
        "finer patches",
        p.fit_residual_deg);
  return s;
}

std::string total_log_line(const Result& r) {
  int iterations = 0;
  for (const PatchReport& p : r.patches) iterations = std::max(iterations, p.iterations);
  return "total: " + std::to_string(r.patches.size()) + " patch(es), " +
         g_abd_change(r.total_before, r.total_after, r.abd_reduction) +
         format("max displacement %.3g AE (AE = %.4g), ", r.total_after.max_disp / r.average_edge,
                r.average_edge) +
         "up to " + std::to_string(iterations) + " iterations, " + std::to_string(r.factorizations) +
         format(" factorisation(s), %.0f ms", r.time_ms);
}

// Step 1 and Step 2 of one solve group, from the input positions.
struct GroupRun {
  GroupMesh group;
  std::vector<PatchFit> fits;
  std::vector<Vec3> targets;  // initial target per group face
  DeformOutcome outcome;
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

GroupRun run_group(const Positions& input, const Positions& V, const Triangles& F,
                   const std::vector<int>& faces, const std::vector<int>& patch,
                   const std::vector<char>& constrained, const std::vector<char>& interior,
                   const VertexFaces& incident, const Params& params, double ae,
                   const std::function<void(double)>& progress) {
  const auto t0 = Clock::now();
  GroupRun run;
  double setup_ms = 0;
  {
    StageTimer timer(setup_ms);
    run.group = extract_group(V, F, faces, patch, constrained, interior, incident, params);
    if (params.tolerance_mode == ToleranceMode::Total) spend_earlier_moves(run.group, input);
  }
  const GroupMesh& g = run.group;
  const size_t threads = static_cast<size_t>(params.threads);
  double step1_ms = 0;
  {
    StageTimer timer(step1_ms);
    run.fits = fit_patches(g, g.V0, threads);
    for (PatchFit& p : run.fits) choose_term(p, params.developability);
    run.targets = group_targets(g, run.fits);
  }
  bool all_idle = true;
  for (const PatchFit& p : run.fits) all_idle = all_idle && p.idle();
  if (all_idle) {
    run.outcome.V = g.V0;
    run.outcome.stop_reason = run.fits.front().skipped.empty()
                                  ? "planar: the Gauss image is a point, nothing to do"
                                  : "left unchanged: " + run.fits.front().skipped;
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

}  // namespace

Result approximate(const Problem& problem, const Progress& progress) {
  const auto t0 = Clock::now();
  const Topology topo = validate(problem);
  const Params& params = problem.params;
  const Positions& V = problem.V;
  const Triangles& F = problem.F;
  const size_t nv = static_cast<size_t>(V.rows()), nf = static_cast<size_t>(F.rows());
  const std::vector<int> patch = problem.patch.empty() ? std::vector<int>(nf, 0) : problem.patch;
  const VertexRoles roles = vertex_roles(problem, topo, params.seams);
  const std::vector<char>& interior = roles.interior;
  const std::vector<char>& constrained = roles.constrained;
  const std::vector<char> held = vertex_roles(problem, topo, SeamMode::Fixed).constrained;
  const VertexFaces incident(F, V.rows());

  Result r;
  r.V = V;
  r.warnings = warnings(topo);
  for (const std::string& w : r.warnings) r.log.push_back("warning: " + w);
  r.average_edge = average_edge_length(V, F);
  const VertexAngles angles_before = vertex_angles(V, F);
  r.k_before = gaussian_curvature(angles_before, interior);
  r.times.setup += ms_since(t0);  // validation, topology, the input's figures

  std::map<int, std::vector<int>> faces_of_patch;
  for (size_t f = 0; f < nf; ++f) faces_of_patch[patch[f]].push_back(static_cast<int>(f));
  // One group per patch, its seams held (the paper). Free seams take three passes, each
  // starting where the one before ended, so none can undo another (never-worse rule): all
  // patches in one group (its one step scale is set by the worst patch, so it stalls early on
  // draped garments), then each patch with its seams held, then each patch again moving its
  // seam vertices (moved by one patch, seen by the next, so they stay shared). Measured on the
  // shared garments, free seams then remove more than fixed ones (issue 11). With a total
  // tolerance each pass moves a vertex only by what the earlier passes left of its budget.
  struct Pass {
    const char* name;                      // in the reports when there are several
    const std::vector<char>* constrained;  // the vertices no group of the pass moves
    size_t first = 0, last = 0;            // its groups
  };
  std::vector<std::vector<int>> groups;
  std::vector<Pass> passes;
  const auto add_pass = [&](const char* name, const std::vector<char>& held_here, bool per_patch) {
    passes.push_back({name, &held_here, groups.size(), 0});
    if (per_patch)
      for (auto& [id, faces] : faces_of_patch) groups.push_back(faces);
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
                                 incident, group_params, r.average_edge, group_progress);
      ++done;
    });
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
      rep.developability = term_name(p.term);
      rep.developability_reason = p.why;
      const bool unfitted = p.idle() && !p.skipped.empty();
      std::string stop = unfitted ? "left unchanged: " + p.skipped : run.outcome.stop_reason;
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
  r.time_ms = ms_since(t0);
  r.log.push_back(total_log_line(r));
  if (progress) progress(100, "done");
  return r;
}

}  // namespace qd
