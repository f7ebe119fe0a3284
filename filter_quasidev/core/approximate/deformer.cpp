#include "approximate/deformer.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "approximate/deformation_system.h"
#include "common/metrics.h"
#include "common/stage_timer.h"

namespace qd {
namespace {

std::vector<int> all_indices(Eigen::Index n) {
  std::vector<int> v(static_cast<size_t>(n));
  std::iota(v.begin(), v.end(), 0);
  return v;
}

// Decrease ratio of Eqs. (19)–(20), percent; 0 when there was nothing left to decrease.
double decrease_ratio(double before, double after) {
  return before > 0 ? 100.0 * (before - after) / before : 0.0;
}

// Face f's normal at V points against its normal at V0, or became degenerate.
bool face_flipped(const Triangles& F, Eigen::Index f, const Positions& V0, const Positions& V) {
  auto cross = [&](const Positions& P) {
    const Vec3 a = P.row(F(f, 0)), b = P.row(F(f, 1)), c = P.row(F(f, 2));
    return Vec3((b - a).cross(c - a));
  };
  return cross(V0).dot(cross(V)) <= 0;
}

// A face that a defect step folds holds its three vertices back where they are, so a few
// faces do not halve the step of the whole patch (issue 11). Repeated while holding back folds
// further faces, up to kFoldRounds times.
constexpr int kFoldRounds = 3;
Positions hold_folding_vertices(const GroupMesh& g, const Positions& current, const Positions& proposed) {
  Positions step = proposed;
  for (int round = 0; round < kFoldRounds; ++round) {
    bool held = false;
    for (Eigen::Index f = 0; f < g.solve_faces; ++f)
      if (face_flipped(g.F, f, g.V0, step)) {
        for (int c = 0; c < 3; ++c) step.row(g.F(f, c)) = current.row(g.F(f, c));
        held = true;
      }
    if (!held) break;
  }
  return step;
}

}  // namespace

Positions clamp_step(const GroupMesh& group, const Positions& current, const Positions& proposed,
                     ToleranceMode mode, ClampMode clamp) {
  const Positions& origin = mode == ToleranceMode::Step ? current : group.V0;
  const auto limit = [&](Eigen::Index v) { return group.tolerance[static_cast<size_t>(v)]; };
  if (mode == ToleranceMode::Step && clamp == ClampMode::Scale) {
    // Departure from §5.2: one factor for the group's step keeps it a least-squares direction.
    double scale = 1.0;
    for (Eigen::Index v = 0; v < group.solve_vertices; ++v) {
      const double len = (proposed.row(v) - current.row(v)).norm();
      if (len > limit(v)) scale = std::min(scale, limit(v) / len);
    }
    return current + scale * (proposed - current);
  }
  Positions out = proposed;  // §5.2: if ‖Δv‖ > δ_err then ‖Δv‖ = δ_err, vertex by vertex
  for (Eigen::Index v = 0; v < out.rows(); ++v) {
    const Vec3 d = (out.row(v) - origin.row(v)).transpose();
    const double len = d.norm();
    if (len > limit(v)) out.row(v) = origin.row(v) + (d * (limit(v) / len)).transpose();
  }
  return out;
}

int flipped_faces(const Triangles& F, const Positions& V0, const Positions& V) {
  int flipped = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) flipped += face_flipped(F, f, V0, V);
  return flipped;
}

DeformOutcome deform(const GroupMesh& group, const std::vector<Vec3>& targets,
                     const Retarget& retarget, const std::vector<char>& defect_rows, const Params& params,
                     double ae, const std::function<void(double)>& progress) {
  const std::vector<int> faces = all_indices(group.solve_faces);
  const std::vector<int> vertices = all_indices(group.solve_vertices);
  DeformOutcome out;
  Figures last;  // figures after the last accepted step
  const auto angles_at = [&](const Positions& X) {
    StageTimer timer(out.times.metrics);
    return vertex_angles(X, group.F);
  };
  const auto figures = [&](const VertexAngles& at_X, const Positions& X,
                           const std::vector<Vec3>& t) {
    StageTimer timer(out.times.metrics);
    return measure(at_X, group.V0, X, group.F, group.owned, faces, t, vertices);
  };

  DeformationSystem system = [&] {  // MLS weights, ordering, sparsity pattern
    StageTimer timer(out.times.setup);
    return DeformationSystem(group, params, ae, defect_rows);
  }();
  out.V = group.V0;
  VertexAngles angles = angles_at(out.V);  // kept at the current positions out.V
  const auto linearised = [&] {  // the defect rows at the current positions
    StageTimer timer(out.times.assembly);
    return system.linearise_defects_at(out.V, angles);
  };
  const bool has_defects = system.has_defect_rows();
  std::vector<Vec3> current_targets = targets;
  system.set_rows(current_targets, linearised());  // Algorithm 1, steps 2.1–2.3

  out.stop_reason = "maxIter reached";
  for (int it = 1; it <= params.max_iter; ++it) {
    const bool retargets = it > 1 && params.targets != TargetMode::Fixed;
    if (retargets) {
      StageTimer timer(out.times.step1);
      current_targets = retarget(out.V);
    }
    if (retargets || (it > 1 && has_defects))  // Gauss–Newton: linearise again at the iterate
      system.set_rows(current_targets, has_defects ? linearised() : DefectLinearisation{});
    // The figures of the current positions: all but the OBD carry over from the last accepted
    // step; the OBD is taken against the current targets.
    Figures before = it == 1 ? figures(angles, out.V, current_targets) : last;
    if (it > 1) {
      StageTimer timer(out.times.metrics);
      before.obd = orientation_developability(out.V, group.F, faces, current_targets);
    }
    // Steps 2.4.1–2.4.3: new right-hand side, back substitution, tolerance check.
    Positions step = clamp_step(group, out.V, system.solve(out.V), params.tolerance_mode,
                                params.clamp);
    IterationReport report;
    report.iteration = it;
    // Never worse (§5.4): the first candidate that folds no face and does not raise G_ABD (one
    // that folds a face is not measured further).
    const auto reject = [&](const std::string& why) {
      report.note += (report.note.empty() ? "" : "; ") + why;
      return false;
    };
    const auto accept = [&](const Positions& candidate, const std::string& label) {
      int flips = 0;
      {
        StageTimer timer(out.times.metrics);
        flips = flipped_faces(group.F, group.V0, candidate);
      }
      if (flips > 0) return reject(label + " flips " + std::to_string(flips) + " face(s)");
      VertexAngles candidate_angles = angles_at(candidate);
      const Figures after = figures(candidate_angles, candidate, current_targets);
      if (!(after.g_abd <= before.g_abd)) return reject(label + " raises G_ABD");
      report.figures = last = after;
      out.V = candidate;
      angles = std::move(candidate_angles);
      return true;
    };
    bool accepted = accept(step, "step ×1.00");
    if (!accepted && has_defects) {
      Positions unfolded;
      {
        StageTimer timer(out.times.metrics);
        unfolded = hold_folding_vertices(group, out.V, step);
      }
      accepted = accept(unfolded, "step with folding faces held");
    }
    for (double scale = 0.5; !accepted && scale >= 0.25; scale *= 0.5) {
      report.step_scale = scale;
      accepted = accept(out.V + scale * (step - out.V), "step ×" + std::to_string(scale).substr(0, 4));
    }
    if (!accepted) {
      out.stop_reason = "never-worse rule: iteration " + std::to_string(it) + " rejected (" +
                        report.note + ")";
      break;
    }
    report.ratio_abd = decrease_ratio(before.g_abd, report.figures.g_abd);  // Eq. (19)
    report.ratio_obd = decrease_ratio(before.obd, report.figures.obd);      // Eq. (20)
    out.history.push_back(report);
    if (progress) progress(static_cast<double>(it) / params.max_iter);
    if (report.ratio_abd < params.stop_abd) {
      out.stop_reason = "ratio_ABD below δ_ABD";
      break;
    }
    // D(P) is comparable between iterations only while the targets stay put (the paper's
    // mode); with re-projected or re-fitted targets only ratio_ABD stops the iteration.
    if (params.targets == TargetMode::Fixed && report.ratio_obd < params.stop_obd) {
      out.stop_reason = "ratio_OBD below δ_OBD";
      break;
    }
  }
  out.times += system.times();
  return out;
}

}  // namespace qd
