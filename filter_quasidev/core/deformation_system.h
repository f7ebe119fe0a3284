// The least-squares system of Step 2 (paper §5.2–5.4) for one group.
//
// Per face t = (v1, v2, v3) with target normal n_t, the 12 rows of Eq. (13) as DESIGN.md reads
// the garbled printed A_i:
//   developability  w·n_tᵀ(v2'−v1') = 0,  w·n_tᵀ(v3'−v2') = 0,  w·n_tᵀ(v1'−v3') = 0
//   shape           (v2'−v1') = (v2−v1),  (v3'−v1') = (v3−v1)          (Eq. 5)
//   centroid        (v1'+v2'+v3')/3 = (v1+v2+v3)/3                      (Eq. 6)
// where v are the reference positions (the current iterate). Columns of a vertex shared by
// several faces are summed (§5.3), so seams cannot open. Constrained vertices are eliminated
// exactly (moved to the right-hand side). Every free vertex gets the soft anchor rows
// α·w(v)·(v' − v0) = 0 with the MLS weight w(v) of Eq. (15): stiffness fades away from the
// constraints. The paper's ‖AWx − c‖ (Eq. 16) rescales the unknowns and constrains nothing, so
// it is not used as written. The normal matrix M = AᵀA + anchors (Eq. 17) depends only on the
// targets and weights: it is factorised once per set of targets and reused for every solve.
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "group_mesh.h"
#include "sparse_cholesky.h"

namespace qd {

class DeformationSystem {
 public:
  // weight: w of Eq. (8); anchor: α; ae: average edge length for Eq. (15).
  DeformationSystem(const GroupMesh& group, double weight, double anchor, double ae);

  // Assembles M for one target normal per group face and factorises it.
  void set_targets(const std::vector<Vec3>& targets);

  // Right-hand side Aᵀc − M_fc·x_c + anchor terms for reference positions `ref`.
  Eigen::VectorXd rhs(const Positions& ref) const;

  // Least-squares positions for reference `ref`: free vertices solved, fixed ones kept.
  Positions solve(const Positions& ref) const;

  const Eigen::SparseMatrix<double>& matrix() const { return M_; }
  // Unknown block of each local vertex (-1 when fixed); unknown 3k+d is coordinate d of block k.
  const std::vector<int>& unknown() const { return unknown_; }
  int factorizations() const { return cholesky_.factorizations(); }

 private:
  const GroupMesh& g_;
  double w_;
  std::vector<double> anchor2_;  // α²·w(v)² per local vertex
  std::vector<int> unknown_;
  int unknowns_ = 0;
  std::vector<Vec3> targets_;
  Eigen::SparseMatrix<double> M_;
  SparseCholesky cholesky_;
};

}  // namespace qd
