// Factorises and solves the quasi-definite augmented system K = [[M, Cᵀ], [C, −I]] of a group
// with angle-defect rows C (deformation_system.h), whose pattern never changes: analysed on the
// first factorisation, refactorised numerically after. K arrives in a fill-reducing order, so no
// back end reorders it. Back ends: QuasiDefiniteLdlt (CHOLMOD's symbolic analysis, our
// supernodal LDLᵀ) for SolverKind::Auto and Cholmod in a build with CHOLMOD; Eigen's
// SimplicialLDLT otherwise (LLᵀ cannot factorise K, so SolverKind::EigenLLT takes it too).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

#include "common/sparse_cholesky.h"

namespace qd {

class QuasiDefiniteSolver {
 public:
  explicit QuasiDefiniteSolver(SolverKind kind);
  ~QuasiDefiniteSolver();
  QuasiDefiniteSolver(const QuasiDefiniteSolver&) = delete;
  QuasiDefiniteSolver& operator=(const QuasiDefiniteSolver&) = delete;

  // Factorises K from its lower triangle; throws qd::Error if K cannot be factorised.
  void factorize(const Eigen::SparseMatrix<double>& lower);
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  int factorizations() const { return factorizations_; }

  struct Backend;

 private:
  SolverKind kind_;
  std::unique_ptr<Backend> backend_;  // made on the first factorisation
  int factorizations_ = 0;
};

}  // namespace qd
