// How one group's linear system (Eq. 17, paper §5.4) is solved: by a factorisation, or by
// conjugate gradients (issue 5).
//
// Direct: M is factorised once per set of targets and every iteration is one back substitution
// (Algorithm 1, steps 2.3–2.4); changed values are factorised again numerically, the analysis
// reused. A group with angle-defect rows solves its quasi-definite K instead, always directly
// (the frames fit those rows too poorly for CG).
//
// Iterative (SolveMethod::Iterative, or Auto from kIterativeFromUnknowns unknowns): CG
// preconditioned by the frame split of frame_preconditioner.h, built once and kept while the
// targets move. Each solve stops when the correction's error in M's energy norm is below
// kCgTolerance of the correction, and starts from the solve before's solution when that is
// closer. Where CG gives up (conjugate_gradients.h: its pace would not reach the tolerance
// within kCgIterations), its iterate is the step all the same, a truncated solve: the point of
// least error in M's energy norm over the directions CG has searched, which the step limit and
// the never-worse rule then judge as every step (on two panels of the upsampled 4-panel tee,
// whose curve targets fit 17–22° off, factorising M instead cost 740 GFlop for less G_ABD
// removed: docs/solvers.md). M solved directly (SolveMethod::Direct) in the order CG wants
// (system_layout.h: from kLeastFillFromBlocks free vertices) is permuted to a LeastFill order
// for its factor. Measurements behind the constants: docs/solvers.md.
#pragma once

#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <vector>

#include "approximate/common_names.h"
#include "approximate/frame_preconditioner.h"
#include "approximate/params.h"
#include "approximate/result.h"
#include "common/block_pattern.h"
#include "common/positive_definite_factor.h"
#include "common/quasi_definite_factor.h"

namespace qd::approximate {

constexpr long kIterativeFromUnknowns = 10000;  // SolveMethod::Auto: CG from here on
// From this many vertex blocks a factorised system is ordered by common::FillOrder::LeastFill
// (AMD or METIS's nested dissection, whichever fills less): on a draped garment's panels of
// 20k–270k vertices nested dissection halves a factorisation's flops, while METIS's ordering
// (1.8 s for 500k vertices) costs more than it saves where CG factorises only the frame
// split's two scalar matrices; on panels of 1.4k–4.3k vertices it saved nothing.
constexpr int kLeastFillFromBlocks = 10000;
constexpr double kCgTolerance = 1e-2;
constexpr int kCgIterations = 40;

class SolveStrategy {
 public:
  // unknowns: M's size; quasi_definite: the group solves K (angle-defect rows); pattern: M's
  // block pattern, for the preconditioner; times: where the stages' times are added;
  // analysis: where the systems with K's pattern keep its analysis (null: not shared).
  SolveStrategy(const Params& params, long unknowns, bool quasi_definite,
                const BlockPattern& pattern, StageTimes& times,
                std::shared_ptr<SharedAnalysis> analysis = nullptr);

  // M's (and K's) values changed: the next direct solve factorises again.
  void values_changed() { factor_current_ = false; }
  // The developability weights changed: the preconditioner's factors are of the old ones.
  void weights_changed() { preconditioner_stale_ = true; }

  // M x = b, M the lower triangle. start(): the reference unknowns, where CG's correction is
  // zero; normals(): one per unknown block, the frames of the preconditioner.
  Eigen::VectorXd solve(const Eigen::SparseMatrix<double>& M, const Eigen::VectorXd& b,
                        const std::function<Eigen::VectorXd()>& start,
                        const std::function<std::vector<Vec3>()>& normals);
  // K z = c, K the lower triangle of the quasi-definite system.
  Eigen::VectorXd solve_quasi_definite(const Eigen::SparseMatrix<double>& K,
                                       const Eigen::VectorXd& c);

  int factorizations() const;
  double factorization_flops() const;  // sparse_factor.h
  // K's factor runs on another back end than the one asked for (eigen-llt cannot factorise K).
  bool substituted() const { return quasi_.factorizations() > 0 && quasi_.substituted(); }

 private:
  Eigen::VectorXd solve_directly(const Eigen::SparseMatrix<double>& M, const Eigen::VectorXd& b);
  // M permuted to a LeastFill order of its blocks, from kLeastFillFromBlocks blocks (else M).
  const Eigen::SparseMatrix<double>& in_factor_order(const Eigen::SparseMatrix<double>& M);
  Eigen::VectorXd solve_iteratively(const Eigen::SparseMatrix<double>& M, const Eigen::VectorXd& b,
                                    const std::function<Eigen::VectorXd()>& start,
                                    const std::function<std::vector<Vec3>()>& normals);

  SolverKind solver_;
  int threads_;
  const bool iterative_;
  const BlockPattern& pattern_;
  StageTimes& times_;
  PositiveDefiniteFactor positive_;                      // M's
  QuasiDefiniteFactor quasi_;                            // K's
  bool factor_current_ = false;                          // the factor belongs to the current values
  std::unique_ptr<FramePreconditioner> preconditioner_;  // built at the first iterative solve
  bool preconditioner_stale_ = false;                    // the weights changed since
  int scalar_factorizations_ = 0;                        // the preconditioner's
  double scalar_flops_ = 0;
  Eigen::VectorXd last_solution_;  // of the last iterative solve: the next one's warm start
  Eigen::PermutationMatrix<Eigen::Dynamic> factor_order_;  // M's unknown i → the factor's
  Eigen::SparseMatrix<double> reordered_;                  // M in that order
};

}  // namespace qd::approximate
