// Sparse Cholesky factorisation of the SPD normal matrix (paper §5.4, Eq. 17): the fill-reducing
// ordering and symbolic analysis are done on the first factorisation and reused afterwards,
// since the sparsity pattern of a group's matrix never changes.
#pragma once

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace qd {

class SparseCholesky {
 public:
  // Factorises M (lower triangle used); throws qd::Error if M is not positive definite.
  void factorize(const Eigen::SparseMatrix<double>& M);
  // Solves M x = b by forward and back substitution with the current factor.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  int factorizations() const { return factorizations_; }

 private:
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> llt_;
  bool analysed_ = false;
  int factorizations_ = 0;
};

}  // namespace qd
