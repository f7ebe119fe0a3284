// The least-squares system of Step 2 (paper §5.2–5.4) for one group.
//
// Per face t = (v1, v2, v3) with target normal n_t, the 12 rows of Eq. (13) as docs/design.md reads
// the garbled printed A_i:
//   developability  w·n_tᵀ(v2'−v1') = 0,  w·n_tᵀ(v3'−v2') = 0,  w·n_tᵀ(v1'−v3') = 0
//   shape           (v2'−v1') = (v2−v1),  (v3'−v1') = (v3−v1)          (Eq. 5)
//   centroid        (v1'+v2'+v3')/3 = (v1+v2+v3)/3                      (Eq. 6)
// where v are the reference positions (the current iterate). Columns of a vertex shared by
// several faces are summed (§5.3), so seams cannot open. Constrained vertices are eliminated
// exactly (moved to the right-hand side). Every free vertex gets the soft anchor rows
// α·w(v)·(v' − v0) = 0 with the MLS weight w(v) of Eq. (15): stiffness fades away from the
// constraints. The paper's ‖AWx − c‖ (Eq. 16) rescales the unknowns and constrains nothing, so
// it is not used as written.
//
// The normal matrix M = AᵀA + anchors (Eq. 17) depends only on the targets and weights. Its
// unknowns are numbered in 3×3 vertex blocks in a fill-reducing order of the vertex graph, and
// it is assembled in place into a sparsity pattern built once; re-projected or re-fitted targets
// change its values only. How it is solved (factorised, or by conjugate gradients) is
// solve_strategy.h's part.
//
// Angle-defect rows C (angle_defect.h; beyond the paper) would add CᵀC to M, which couples every
// pair of vertices of a star and makes M's factor about three times dearer (docs/solvers.md).
// They are kept apart instead, one multiplier y per row, in the quasi-definite system
//   K [x; y] = [[M, Cᵀ], [C, −I]] [x; y] = [b; d],  so that (M + CᵀC) x = b + Cᵀd,
// the same least-squares solution, numbered in M's vertex order and factorised by LDLᵀ
// (quasi_definite_factor.h). The order, the patterns and K's analysis are the layout's
// (system_layout.h), which the systems of one group may share.
#pragma once

#include <Eigen/SparseCore>
#include <optional>
#include <vector>

#include "approximate/angle_defect.h"
#include "approximate/common_names.h"
#include "approximate/group_mesh.h"
#include "approximate/result.h"
#include "approximate/solve_strategy.h"
#include "approximate/system_layout.h"
#include "common/block_pattern.h"

namespace qd::approximate {

class DeformationSystem {
 public:
  // From params: w of Eq. (8), α of Eq. (15), the solver, the method and the threads this
  // group may use; ae: average edge length for Eq. (15); defect_rows: per local vertex, 1 =
  // it gets an angle-defect row (angle_defect.h; empty = none).
  DeformationSystem(const GroupMesh& group, const Params& params, double ae,
                    const std::vector<char>& defect_rows = {});
  // On a layout of the group's (SystemLayouts::get), for the same params but w_d: the rows are
  // weighed for params.defect_weight whatever weight the layout's were made for.
  DeformationSystem(const GroupMesh& group, const Params& params, SystemLayout layout);

  // Assembles M (Eq. 17) for one target normal per group face (a zero vector: no
  // developability rows of Eq. 13 for that face) and the angle-defect rows linearised at the
  // reference positions of the next solve (empty when the group has none).
  void set_rows(const std::vector<Vec3>& targets, const DefectLinearisation& defects = {});

  // Multiplies w (Eq. 8) and every angle-defect row's weight by `factor`; set_rows must follow.
  void scale_developability(double factor);

  bool has_defect_rows() const { return !defects_.empty(); }
  // The soft anchors (Eq. 15) hold the free vertices to X from now on instead of the input.
  void move_anchors(const Positions& X) { moved_anchors_ = X; }
  // The angle-defect rows linearised at X (angles: vertex_angles of X), for set_rows.
  DefectLinearisation linearise_defects_at(const Positions& X, const VertexAngles& angles) const {
    return linearise_defects(defects_, g_, m_.incident, X, angles);
  }

  // Right-hand side Aᵀc − M_fc·x_c + anchor terms for reference positions `ref` (the defect
  // rows' part is added in the solve).
  Eigen::VectorXd rhs(const Positions& ref) const;

  // Least-squares positions for reference `ref`: free vertices solved, fixed ones kept.
  Positions solve(const Positions& ref);

  // Lower triangle of M (the defect rows' CᵀC is not in it: they stay in K); unknown 3k+d is
  // coordinate d of block k.
  const Eigen::SparseMatrix<double>& matrix() const { return M_; }
  // Unknown block of each local vertex (-1 when fixed).
  const std::vector<int>& unknown() const { return m_.unknown; }
  const StageTimes& times() const { return times_; }

 private:
  void set_augmented_values();
  Eigen::VectorXd defect_rhs(const Positions& ref) const;
  Eigen::VectorXd solve_augmented(const Eigen::VectorXd& b, const Positions& ref);
  std::vector<Vec3> frame_normals() const;
  Eigen::VectorXd unknowns_of(const Positions& X) const;

  const GroupMesh& g_;
  double w_;
  SystemLayout layout_;
  const MatrixLayout& m_;  // *layout_.matrix
  std::vector<Vec3> targets_;
  DefectStars defects_;  // the layout's, with the weights scaled
  DefectLinearisation linearised_;
  Eigen::SparseMatrix<double> M_;
  int threads_;
  Eigen::SparseMatrix<double> K_;  // lower triangle of [[M, Cᵀ], [C, −I]] (defect rows C)
  StageTimes times_;
  std::optional<SolveStrategy> strategy_;  // chosen once the system's size is known
  Positions moved_anchors_;                // where the anchors hold once moved (empty: V0)
};

}  // namespace qd::approximate
