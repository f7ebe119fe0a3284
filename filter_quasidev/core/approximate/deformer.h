// Step 2 of Algorithm 1 (paper §5.4) for one group, one iteration at a time: solve → clamp to
// δ_err → accept, until a stop rule ends the run.
//
// Acceptance (the never-worse rule, beyond the paper): a candidate step that folds a face (its
// normal turns against the engine's input one, GroupMesh::V_input) is refused; one whose G_ABD
// exceeds the best iterate's by more than kRiseAllowance is refused. A refused step is shortened:
// with angle-defect rows, first with the vertices of its folding faces held back, then halved down
// to kMinStepScale. The iteration is then solved again with the developability weights (w of Eq. 8
// and w_d) divided by kWeightBackoff, down to kMinWeightScale, for this and the later iterations: a
// weaker pull toward developability gives a smoother step where the strong one folds faces
// (damping, as in Levenberg–Marquardt). With the curve targets alone a refused full step is solved
// again at once, before any shortening, while the weights can still go down: on the generated
// family that took the curve term from 69 % to 99 % on bumps of 1 AE, where the angle-defect rows
// lost curvature removed that way on the garments (docs/robustness.md). The run returns its best
// iterate, so it never hands back a mesh with more curvature than it was given. The small allowed
// rise lets a run leave a kink of G_ABD (a sum of absolute values: a vertex whose defect is 0 rises
// at first order whichever way it moves), where a strict descent stalls at iteration 1.
//
// Stop rules (StopRule): Plateau (default) stops when the best G_ABD fell by less than δ_ABD
// percent over the last kPlateauIterations iterations; Paper stops at the first iteration whose
// ratio_ABD (Eq. 19) is below δ_ABD, or ratio_OBD (Eq. 20) below δ_OBD with fixed targets.
// Both also stop at maxIter and when no step down to kMinStepScale is accepted.
//
// TargetMode::ReprojectThenRefit (the default; beyond the paper; Plateau rule only): where a run
// with curve targets would stop at a plateau or for want of a step, the Gauss-image curve is
// fitted again to the current normals and the run goes on with re-fitted targets until a plateau
// of its own, once. The curve fitted to the input's normals is one the surface may have moved
// off; its targets stall where another curve's do not. On the generated family of
// scripts/robustness_sweep.py this took the curve term on a plane with bumps of 2 AE from 36 %
// to 100 % of G_ABD removed, and auto (with term_race.h's rules) further on 26 members, less on
// none. A run that gains nothing from the re-fit costs kPlateauIterations iterations more
// (docs/robustness.md has what the garments pay).
//
// Moved anchors (beyond the paper; Plateau rule only): where a run with angle-defect rows would
// stop at a plateau, the soft anchors of Eq. (15) move from the input to the current positions
// and the run goes on until a plateau of its own, once. The rows stall where their pull balances
// the anchors' pull back to the input, not where the surface is developable (what it gains on
// the generated family and costs the garments: docs/robustness.md).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "approximate/common_names.h"
#include "approximate/group_mesh.h"
#include "approximate/params.h"
#include "approximate/result.h"
#include "approximate/system_layout.h"
#include "common/progress.h"

namespace qd::approximate {

constexpr double kRiseAllowance = 0.1;  // accepted G_ABD ≤ (1 + this) · best so far
constexpr double kMinStepScale = 1.0 / 16;
constexpr int kPlateauIterations = 3;  // Plateau's window
constexpr double kWeightBackoff = 3.0;
constexpr double kMinWeightScale = 1.0 / 9;

// New target normal per group face for the current positions (re-projection or re-fit).
using Retarget = std::function<std::vector<Vec3>(const Positions& current, TargetMode mode)>;

// What a run gives: the best iterate, its history, and why it stopped.
struct DeformOutcome {
  Positions V;                           // the best iterate's local positions
  std::vector<IterationReport> history;  // accepted iterations up to the best one
  int iterations_run = 0;                // accepted iterations, including those after the best
  PatchStop stop = PatchStop::MaxIter;
  std::string stop_detail;       // NoStep: the refused candidates; Unfitted: why
  double plateau_removed = 0;    // Plateau: percent of G_ABD the last iterations removed
  int refit_after = -1;          // accepted iterations before the curve was re-fitted; -1: never
  bool refit_behind = false;     // re-fitted by auto's race (term_race.h), not at a stall
  int anchors_moved_after = -1;  // accepted iterations before the anchors moved; -1: never
  StageTimes times;              // assembly, factorisation, solve, re-targeting, metrics
};

class DeformationSystem;

class Deformation {
 public:
  // targets: initial target per group face (zero: no Eq. 13 developability rows for it);
  // retarget: used between iterations unless params.targets == TargetMode::Fixed;
  // refits: whether the run fits its curves again when it stalls (above; refits_when_stalled);
  // layouts: the group's (for the same params), which the runs on it share; defect_rows: per
  // local vertex, 1 = an angle-defect row (angle_defect.h; empty = none).
  Deformation(const GroupMesh& group, std::vector<Vec3> targets, Retarget retarget, bool refits,
              SystemLayouts& layouts, const std::vector<char>& defect_rows, const Params& params);
  ~Deformation();
  Deformation(Deformation&&) noexcept;

  // One iteration; false once the run has stopped.
  bool step();
  bool running() const { return !stopped_; }
  PatchStop stop_reason() const { return out_.stop; }  // once stopped
  int iterations() const { return out_.iterations_run; }
  double initial_g_abd() const { return initial_g_; }
  double best_g_abd() const { return best_.g_abd; }
  const Figures& best() const { return best_; }     // the best iterate's figures
  const Figures& current() const { return last_; }  // the last accepted iterate's
  // Whether the never-worse rule refused the last iteration's full step at the weights it began
  // with: the accepted step was shortened, or solved again with weaker developability weights.
  bool last_full_step_refused() const {
    const size_t n = out_.history.size();
    if (n == 0) return false;
    const double weights_before = n > 1 ? out_.history[n - 2].weight_scale : 1;
    return out_.history.back().step_scale < 1 || out_.history.back().weight_scale < weights_before;
  }
  // The best G_ABD after each accepted iteration ([0]: the input's).
  const std::vector<double>& best_track() const { return best_track_; }
  // Accepted iterations since the current phase began (the input, re-fitted targets, moved
  // anchors): the plateau rule judges a pace only over iterations of one phase.
  int phase_iterations() const { return static_cast<int>(best_track_.size() - 1 - plateau_from_); }
  // Whether the anchors moved at a plateau of the run's angle-defect rows (move_anchors below).
  bool anchors_moved() const { return out_.anchors_moved_after >= 0; }
  // From the next iteration on, fits the curve again and goes on with re-fitted targets to a
  // plateau of their own (above; what a stalled run does), once; false: it cannot (not asked
  // for, already done). behind: asked by auto's race, where these targets fell far behind.
  bool refit_targets(bool behind = false);
  // From now on an iterate becomes the best only where `within` holds for its figures (auto's
  // stronger rows, bounded by a move: group_run.h).
  void keep_best_within(std::function<bool(const Figures&)> within) { within_ = std::move(within); }
  // The result (call once, after the last step).
  DeformOutcome finish();

 private:
  bool accept(const Positions& candidate, const std::string& label, IterationReport& report,
              const Figures& before);
  bool accept_shortened(const Positions& step, IterationReport& report, const Figures& before);
  void set_rows();
  void check_stop(const IterationReport& report);
  // At a plateau of a run with angle-defect rows: the anchors hold to the current positions
  // from now on, and the run goes on to a plateau of its own (once); false: it cannot.
  bool move_anchors();
  // A new phase (re-fitted targets, moved anchors) starts here: the plateau window restarts.
  // Returns the accepted iterations before it.
  int start_phase() {
    plateau_from_ = best_track_.size() - 1;
    return out_.iterations_run;
  }
  // Ends the run (out_.stop says why; a run that never halts stopped at maxIter).
  void halt(PatchStop why) {
    out_.stop = why;
    stopped_ = true;
  }

  const GroupMesh& g_;
  Params params_;
  std::vector<Vec3> targets_;
  Retarget retarget_;
  std::unique_ptr<DeformationSystem> system_;
  std::vector<int> faces_, vertices_;
  Positions V_;          // current iterate
  VertexAngles angles_;  // at V_
  Figures last_;         // figures of V_
  Figures best_;         // figures of the best iterate
  Positions best_V_;
  std::function<bool(const Figures&)> within_;  // empty: any iterate may be the best
  std::vector<double> best_track_;  // best G_ABD after each accepted iteration (0: the input)
  size_t best_iterations_ = 0;      // accepted iterations up to the best iterate
  double initial_g_ = 0;
  double weight_scale_ = 1;  // of the developability weights, after back-offs
  int it_ = 0;
  bool stopped_ = false;
  bool refits_;              // fits its curves again when it stalls (above)
  TargetMode mode_;          // of the re-targeting now
  size_t plateau_from_ = 0;  // best_track_ index where the plateau window may start
  DeformOutcome out_;
};

// The whole run at once.
DeformOutcome deform(const GroupMesh& group, const std::vector<Vec3>& targets,
                     const Retarget& retarget, bool refits, const std::vector<char>& defect_rows,
                     const Params& params, double ae, const std::function<void(double)>& progress);

// Limits the step from `current` to `proposed` by the group's δ_err (§5.2). Step mode:
// |Δv| ≤ δ_err for every vertex, by scaling the whole step (ClampMode::Scale) or clamping each
// vertex (ClampMode::Vertex, the paper's). Total mode: |v' − v0| ≤ δ_err, vertex by vertex.
Positions clamp_step(const GroupMesh& group, const Positions& current, const Positions& proposed,
                     ToleranceMode mode, ClampMode clamp);

// Number of faces whose normal at V points against their normal at V0 (or became degenerate).
int flipped_faces(const Triangles& F, const Positions& V0, const Positions& V);

}  // namespace qd::approximate
