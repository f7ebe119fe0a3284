// A preconditioner for the coupled system M (Eq. 17) built from two scalar factorisations, so
// the 3n×3n matrix is never factorised (issue 5). The developability rows w·n_tᵀ(v'−v) make M
// stiff (w² ≫ 1) along the target normals and soft across them. In a frame per vertex (a unit
// normal ν, the mean of the targets around it, and two tangents t₁, t₂) M splits into fields:
//   K_n(u,v) = ν_uᵀ M_uv ν_v                              normal displacements
//   K_t(u,v) = ½ (t₁,uᵀ M_uv t₁,v + t₂,uᵀ M_uv t₂,v)     tangential ones (both share K_t)
// (Galerkin restrictions of M; M_uv its 3×3 block). P⁻¹r splits r into frame components,
// solves K_n and K_t (two right-hand sides), and recombines. K_n and K_t have the vertex
// graph's pattern and order, so one analysis serves every factorisation.
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "approximate/common_names.h"
#include "common/block_pattern.h"
#include "common/mesh.h"
#include "common/positive_definite_factor.h"

namespace qd::approximate {

class FramePreconditioner {
 public:
  // threads: how many of the two factorisations (and solves) may run at once.
  FramePreconditioner(const BlockPattern& pattern, SolverKind solver, int threads);

  // Frames from one normal per unknown block (need not be unit; a zero one gets any frame),
  // the restrictions of M (lower triangle, BlockPattern layout) and their factorisations.
  void build(const Eigen::SparseMatrix<double>& M, const std::vector<Vec3>& normals);

  // P⁻¹ r.
  Eigen::VectorXd apply(const Eigen::VectorXd& r) const;

  int factorizations() const { return normal_.factorizations() + tangent_.factorizations(); }
  double flops() const { return normal_.flops() + tangent_.flops(); }
  double entries() const { return normal_.entries() + tangent_.entries(); }  // of both factors

 private:
  void set_frames(const std::vector<Vec3>& normals);
  void restrict_to_frames(const Eigen::SparseMatrix<double>& M);

  const BlockPattern& pattern_;
  size_t threads_;
  std::vector<Eigen::Matrix3d> frame_;  // per block, rows ν, t₁, t₂
  Eigen::SparseMatrix<double> K_n_, K_t_;
  PositiveDefiniteFactor normal_, tangent_;
};

}  // namespace qd::approximate
