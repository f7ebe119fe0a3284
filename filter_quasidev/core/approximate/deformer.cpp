#include "approximate/deformer.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "approximate/common_names.h"
#include "approximate/deformation_system.h"
#include "common/metrics.h"
#include "common/stage_timer.h"

namespace qd::approximate {
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
Positions hold_folding_vertices(const GroupMesh& g, const Positions& current,
                                const Positions& proposed) {
  Positions step = proposed;
  for (int round = 0; round < kFoldRounds; ++round) {
    bool held = false;
    for (Eigen::Index f = 0; f < g.solve_faces; ++f)
      if (face_flipped(g.F, f, g.V_input, step)) {
        for (int c = 0; c < 3; ++c) step.row(g.F(f, c)) = current.row(g.F(f, c));
        held = true;
      }
    if (!held) break;
  }
  return step;
}

std::string scale_label(double scale) {
  return scale == 1.0 ? "step ×1"
                      : "step ×1/" + std::to_string(static_cast<int>(std::lround(1 / scale)));
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

Deformation::Deformation(const GroupMesh& group, std::vector<Vec3> targets, Retarget retarget,
                         bool refits, SystemLayouts& layouts, const std::vector<char>& defect_rows,
                         const Params& params)
    : g_(group),
      params_(params),
      targets_(std::move(targets)),
      retarget_(std::move(retarget)),
      faces_(all_indices(group.solve_faces)),
      vertices_(all_indices(group.solve_vertices)),
      V_(group.V0),
      refits_(refits),
      mode_(params.targets == TargetMode::ReprojectThenRefit ? TargetMode::Reproject
                                                             : params.targets) {
  {
    StageTimer timer(out_.times.setup);  // the layout's parts not yet computed
    system_ = std::make_unique<DeformationSystem>(g_, params_, layouts.get(defect_rows));
  }
  {
    StageTimer timer(out_.times.metrics);
    angles_ = vertex_angles(V_, g_.F);
    last_ = best_ = measure(angles_, g_.V0, V_, g_.F, g_.owned, faces_, targets_, vertices_);
  }
  initial_g_ = best_.g_abd;
  best_V_ = V_;
  best_track_.push_back(best_.g_abd);
  set_rows();  // Algorithm 1, steps 2.1–2.3
}

// The rows for the current targets, the angle defects linearised at V_ (Gauss–Newton).
void Deformation::set_rows() {
  DefectLinearisation defects;
  if (system_->has_defect_rows()) {
    StageTimer timer(out_.times.assembly);  // the system times its own assembly
    defects = system_->linearise_defects_at(V_, angles_);
  }
  system_->set_rows(targets_, defects);
}

// The step, or with angle-defect rows the step with its folding faces held back, or the step
// halved down to kMinStepScale: the first that accept() takes.
bool Deformation::accept_shortened(const Positions& step, IterationReport& report,
                                   const Figures& before) {
  if (accept(step, scale_label(1), report, before)) return true;
  if (system_->has_defect_rows()) {
    Positions unfolded;
    {
      StageTimer timer(out_.times.metrics);
      unfolded = hold_folding_vertices(g_, V_, step);
    }
    if (accept(unfolded, "step with folding faces held", report, before)) return true;
  }
  for (double scale = 0.5; scale >= kMinStepScale; scale *= 0.5) {
    report.step_scale = scale;
    if (accept(V_ + scale * (step - V_), scale_label(scale), report, before)) return true;
  }
  return false;
}

Deformation::~Deformation() = default;
Deformation::Deformation(Deformation&&) noexcept = default;

bool Deformation::accept(const Positions& candidate, const std::string& label,
                         IterationReport& report, const Figures& before) {
  const auto refuse = [&](const std::string& why) {
    report.note += (report.note.empty() ? "" : "; ") + label + " " + why;
    return false;
  };
  int flips = 0;
  {
    StageTimer timer(out_.times.metrics);
    flips = flipped_faces(g_.F, g_.V_input, candidate);
  }
  if (flips > 0) return refuse("flips " + std::to_string(flips) + " face(s)");
  VertexAngles angles;
  Figures after;
  {
    StageTimer timer(out_.times.metrics);
    angles = vertex_angles(candidate, g_.F);
    after = measure(angles, g_.V0, candidate, g_.F, g_.owned, faces_, targets_, vertices_);
  }
  if (!(after.g_abd <= (1 + kRiseAllowance) * best_.g_abd)) return refuse("raises G_ABD");
  report.figures = last_ = after;
  report.ratio_abd = decrease_ratio(before.g_abd, after.g_abd);  // Eq. (19)
  report.ratio_obd = decrease_ratio(before.obd, after.obd);      // Eq. (20)
  V_ = candidate;
  angles_ = std::move(angles);
  return true;
}

bool Deformation::step() {
  if (!running()) return false;
  if (it_ == params_.max_iter) {
    halt(PatchStop::MaxIter);
    return false;
  }
  ++it_;
  const bool retargets = it_ > 1 && params_.targets != TargetMode::Fixed;
  if (retargets) {
    StageTimer timer(out_.times.step1);
    targets_ = retarget_(V_, mode_);
  }
  if (retargets || (it_ > 1 && system_->has_defect_rows())) set_rows();  // linearise again
  // The figures of the current positions: all but the OBD carry over from the last accepted
  // step; the OBD is taken against the current targets.
  Figures before = last_;
  if (it_ > 1) {
    StageTimer timer(out_.times.metrics);
    before.obd = orientation_developability(V_, g_.F, faces_, targets_);
  }
  IterationReport report;
  report.iteration = it_;
  for (;;) {
    report.step_scale = 1;
    // Steps 2.4.1–2.4.3: new right-hand side, back substitution, tolerance check.
    const Positions step =
        clamp_step(g_, V_, system_->solve(V_), params_.tolerance_mode, params_.clamp);
    // A refused full step is solved again with weaker developability weights while they can
    // be (with angle-defect rows only once no shortened step is accepted); at the weakest, it
    // is shortened.
    const bool can_back_off = weight_scale_ / kWeightBackoff >= kMinWeightScale * (1 - 1e-9);
    const bool shorten_first = system_->has_defect_rows() || !can_back_off;
    if (shorten_first ? accept_shortened(step, report, before)
                      : accept(step, scale_label(1), report, before))
      break;
    if (!can_back_off) {
      if (refit_targets()) return true;  // the next iteration re-fits
      halt(PatchStop::NoStep);
      out_.stop_detail = report.note;
      return false;
    }
    weight_scale_ /= kWeightBackoff;
    system_->scale_developability(1 / kWeightBackoff);
    set_rows();
    report.note += "; solved again with the developability weights ×1/" +
                   std::to_string(static_cast<int>(std::lround(1 / weight_scale_)));
  }
  report.weight_scale = weight_scale_;
  out_.history.push_back(report);
  ++out_.iterations_run;
  if (last_.g_abd < best_.g_abd && (!within_ || within_(last_))) {
    best_ = last_;
    best_V_ = V_;
    best_iterations_ = out_.history.size();
  }
  best_track_.push_back(best_.g_abd);
  check_stop(report);
  return running();
}

void Deformation::check_stop(const IterationReport& report) {
  if (params_.stop_rule == StopRule::Paper) {
    if (report.ratio_abd < params_.stop_abd) {
      halt(PatchStop::RatioAbd);
    } else if (params_.targets == TargetMode::Fixed && report.ratio_obd < params_.stop_obd) {
      // D(P) is comparable between iterations only while the targets stay put (the paper's
      // mode); with re-projected or re-fitted targets only ratio_ABD stops the iteration.
      halt(PatchStop::RatioObd);
    }
    return;
  }
  const size_t n = best_track_.size();
  // The window starts at the input, or where the targets were re-fitted.
  if (n - 1 - plateau_from_ < static_cast<size_t>(kPlateauIterations)) return;
  const double removed =
      decrease_ratio(best_track_[n - 1 - kPlateauIterations], best_track_[n - 1]);
  if (removed >= params_.stop_abd) return;
  if (refit_targets()) return;  // the next iteration re-fits
  if (move_anchors()) return;
  halt(PatchStop::Plateau);
  out_.plateau_removed = removed;
}

bool Deformation::refit_targets(bool behind) {
  if (!refits_ || mode_ != TargetMode::Reproject || !running()) return false;
  mode_ = TargetMode::Refit;
  out_.refit_after = start_phase();
  out_.refit_behind = behind;
  return true;
}

bool Deformation::move_anchors() {
  if (!system_->has_defect_rows() || out_.anchors_moved_after >= 0 || !running()) return false;
  system_->move_anchors(V_);
  out_.anchors_moved_after = start_phase();
  return true;
}

DeformOutcome Deformation::finish() {
  out_.history.resize(best_iterations_);  // the best iterate, and the history up to it
  out_.V = std::move(best_V_);
  out_.times += system_->times();
  return std::move(out_);
}

DeformOutcome deform(const GroupMesh& group, const std::vector<Vec3>& targets,
                     const Retarget& retarget, bool refits, const std::vector<char>& defect_rows,
                     const Params& params, double ae, const std::function<void(double)>& progress) {
  SystemLayouts layouts(group, params, ae);
  Deformation run(group, targets, retarget, refits, layouts, defect_rows, params);
  while (run.step())
    if (progress) progress(static_cast<double>(run.iterations()) / params.max_iter);
  return run.finish();
}

}  // namespace qd::approximate
