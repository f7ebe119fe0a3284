#include "approximate/deformer.h"

#include <algorithm>
#include <cmath>
#include <map>
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

// Per patch of a group: its faces, and its owned vertices (a seam vertex counts in each).
struct GroupPatches {
  std::vector<int> face_part;                 // part of each solved face
  std::vector<std::vector<int>> owned;        // per part
};

GroupPatches group_patches(const GroupMesh& g) {
  GroupPatches p;
  std::map<int, int> part_of_id;
  for (Eigen::Index f = 0; f < g.solve_faces; ++f)
    p.face_part.push_back(part_of_id.emplace(g.face_patch[static_cast<size_t>(f)],
                                             static_cast<int>(part_of_id.size())).first->second);
  std::vector<char> is_owned(g.fixed.size(), 0);
  for (int v : g.owned) is_owned[static_cast<size_t>(v)] = 1;
  p.owned.resize(part_of_id.size());  // not a flag per vertex and part: patches × vertices
  for (Eigen::Index f = 0; f < g.solve_faces; ++f)
    for (int c = 0; c < 3; ++c)
      if (is_owned[static_cast<size_t>(g.F(f, c))])
        p.owned[static_cast<size_t>(p.face_part[static_cast<size_t>(f)])].push_back(g.F(f, c));
  for (std::vector<int>& owned : p.owned) {
    std::sort(owned.begin(), owned.end());
    owned.erase(std::unique(owned.begin(), owned.end()), owned.end());
  }
  return p;
}

// Σ|K(v)| over each part's owned vertices at X (Eq. 18).
std::vector<double> part_g_abd(const GroupMesh& g, const GroupPatches& parts, const Positions& X) {
  const VertexAngles angles = vertex_angles(X, g.F);
  std::vector<double> sums;
  for (const std::vector<int>& owned : parts.owned) {
    double sum = 0;
    for (int v : owned)
      if (angles.area[static_cast<size_t>(v)] > 0)
        sum += std::abs(angles.defect[static_cast<size_t>(v)] / angles.area[static_cast<size_t>(v)]);
    sums.push_back(sum);
  }
  return sums;
}

// With free seams a group holds several patches, and one patch whose part of the step folds a
// face or raises its G_ABD would make the never-worse rule shorten or reject every patch's
// step. Such a patch's part is halved instead, and held back (its vertices, seams included,
// keep their place) after three halvings, while the other patches keep theirs (issue 11). A
// seam vertex takes the smallest factor of its patches.
// `shortened` counts the patches whose part was halved or held back.
Positions hold_worse_patches(const GroupMesh& g, const GroupPatches& parts, const Positions& current,
                             const Positions& proposed, int& shortened) {
  const std::vector<double> before = part_g_abd(g, parts, current);
  std::vector<double> part_scale(before.size(), 1.0);
  Positions step = proposed;
  for (int round = 0; round < 4; ++round) {
    const std::vector<double> after = part_g_abd(g, parts, step);
    std::vector<char> worse(before.size(), 0);
    for (size_t k = 0; k < before.size(); ++k) worse[k] = part_scale[k] > 0 && after[k] > before[k];
    for (Eigen::Index f = 0; f < g.solve_faces; ++f) {
      const auto k = static_cast<size_t>(parts.face_part[static_cast<size_t>(f)]);
      if (part_scale[k] > 0 && face_flipped(g.F, f, g.V0, step)) worse[k] = 1;
    }
    if (std::find(worse.begin(), worse.end(), 1) == worse.end()) break;
    for (size_t k = 0; k < part_scale.size(); ++k)
      if (worse[k]) part_scale[k] = round < 3 ? 0.5 * part_scale[k] : 0.0;
    std::vector<double> vertex_scale(static_cast<size_t>(step.rows()), 1.0);
    for (Eigen::Index f = 0; f < g.solve_faces; ++f)
      for (int c = 0; c < 3; ++c) {
        double& scale = vertex_scale[static_cast<size_t>(g.F(f, c))];
        scale = std::min(scale, part_scale[static_cast<size_t>(parts.face_part[static_cast<size_t>(f)])]);
      }
    for (Eigen::Index v = 0; v < step.rows(); ++v)
      step.row(v) = current.row(v) + vertex_scale[static_cast<size_t>(v)] * (proposed.row(v) - current.row(v));
  }
  shortened = static_cast<int>(std::count_if(part_scale.begin(), part_scale.end(), [](double x) { return x < 1; }));
  return step;
}

}  // namespace

Positions clamp_step(const GroupMesh& group, const Positions& current, const Positions& proposed,
                     ToleranceMode mode, ClampMode clamp) {
  const Positions& origin = mode == ToleranceMode::Step ? current : group.V0;
  const auto limit = [&](Eigen::Index v) { return group.tolerance[static_cast<size_t>(v)]; };
  if (mode == ToleranceMode::Step && clamp == ClampMode::Scale) {
    // Departure from §5.2: one factor per patch keeps its step a least-squares direction. A
    // seam vertex takes the smallest factor of its patches, so with free seams the worst
    // vertex of one patch cannot shrink every other patch's step (issue 11).
    std::map<int, double> patch_scale;
    for (Eigen::Index f = 0; f < group.solve_faces; ++f) {
      double& scale = patch_scale.emplace(group.face_patch[static_cast<size_t>(f)], 1.0).first->second;
      for (int c = 0; c < 3; ++c) {
        const Eigen::Index v = group.F(f, c);
        const double len = (proposed.row(v) - current.row(v)).norm();
        if (len > limit(v)) scale = std::min(scale, limit(v) / len);
      }
    }
    std::vector<double> vertex_scale(static_cast<size_t>(proposed.rows()), 1.0);
    std::vector<char> seen(vertex_scale.size(), 0);
    for (Eigen::Index f = 0; f < group.solve_faces; ++f)
      for (int c = 0; c < 3; ++c) {
        const auto v = static_cast<size_t>(group.F(f, c));
        const double scale = patch_scale[group.face_patch[static_cast<size_t>(f)]];
        vertex_scale[v] = seen[v]++ ? std::min(vertex_scale[v], scale) : scale;
      }
    Positions out = proposed;
    for (Eigen::Index v = 0; v < out.rows(); ++v)
      out.row(v) = current.row(v) + vertex_scale[static_cast<size_t>(v)] * (proposed.row(v) - current.row(v));
    return out;
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
  auto figures = [&](const Positions& X, const std::vector<Vec3>& t) {
    StageTimer timer(out.times.metrics);
    return measure(group.V0, X, group.F, group.owned, faces, t, vertices);
  };

  DeformationSystem system = [&] {  // MLS weights, ordering, sparsity pattern
    StageTimer timer(out.times.setup);
    return DeformationSystem(group, params, ae, defect_rows);
  }();
  const auto linearised = [&](const Positions& X) {  // the defect rows at X
    StageTimer timer(out.times.assembly);
    return system.linearise_defects_at(X);
  };
  const bool has_defects = system.has_defect_rows();
  const GroupPatches parts = group_patches(group);
  std::vector<Vec3> current_targets = targets;
  system.set_rows(current_targets, linearised(group.V0));  // Algorithm 1, steps 2.1–2.3

  out.V = group.V0;
  out.stop_reason = "maxIter reached";
  for (int it = 1; it <= params.max_iter; ++it) {
    const bool retargets = it > 1 && params.targets != TargetMode::Fixed;
    if (retargets) {
      StageTimer timer(out.times.step1);
      current_targets = retarget(out.V);
    }
    if (retargets || (it > 1 && has_defects))  // Gauss–Newton: linearise again at the iterate
      system.set_rows(current_targets, has_defects ? linearised(out.V) : DefectLinearisation{});
    // The figures of the current positions: all but the OBD carry over from the last accepted
    // step; the OBD is taken against the current targets.
    Figures before = it == 1 ? figures(out.V, current_targets) : last;
    if (it > 1) {
      StageTimer timer(out.times.metrics);
      before.obd = orientation_developability(out.V, group.F, faces, current_targets);
    }
    // Steps 2.4.1–2.4.3: new right-hand side, back substitution, tolerance check.
    Positions step = clamp_step(group, out.V, system.solve(out.V), params.tolerance_mode,
                                params.clamp);
    IterationReport report;
    report.iteration = it;
    int shortened = 0;
    if (parts.owned.size() > 1) {
      StageTimer timer(out.times.metrics);
      step = hold_worse_patches(group, parts, out.V, step, shortened);
      if (shortened > 0) report.note = std::to_string(shortened) + " patch(es) shortened or held back";
    }
    bool accepted = false;
    for (double scale = 1.0; scale >= 0.25; scale *= 0.5) {
      const Positions candidate = out.V + scale * (step - out.V);
      int flips = 0;
      {
        StageTimer timer(out.times.metrics);
        flips = flipped_faces(group.F, group.V0, candidate);
      }
      const Figures after = figures(candidate, current_targets);
      if (flips == 0 && after.g_abd <= before.g_abd) {
        report.figures = last = after;
        report.step_scale = scale;
        out.V = candidate;
        accepted = true;
        break;
      }
      report.note += (report.note.empty() ? "" : "; ") + std::string("step ×") +
                     std::to_string(scale).substr(0, 4) +
                     (flips ? " flips " + std::to_string(flips) + " face(s)" : " raises G_ABD");
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
    if (report.ratio_abd < params.stop_abd && shortened == 0) {  // a held-back patch may go on
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
