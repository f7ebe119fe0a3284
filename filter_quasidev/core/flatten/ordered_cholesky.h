// Sparse Cholesky of an SPD matrix in a fill-reducing order: the engine's PositiveDefiniteFactor
// (CHOLMOD or Eigen's simplicial factor, positive_definite_factor.h) expects its matrix ordered
// already, so this orders the matrix's own graph by minimum degree (vertex_order.h), permutes
// it symmetrically and undoes the permutation on every solve.
#pragma once

#include <Eigen/SparseCore>

#include "common/positive_definite_factor.h"
#include "flatten/common_names.h"

namespace qd::flatten {

class OrderedCholesky {
 public:
  // Factorises M (both triangles stored); solves as in PositiveDefiniteFactor. Throws
  // qd::common::Error if M is not positive definite.
  OrderedCholesky(const Eigen::SparseMatrix<double>& M, SolverKind kind, Solves solves);
  // Solves M x = b for every column of b.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;

 private:
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order_;  // old → new index
  PositiveDefiniteFactor cholesky_;
};

}  // namespace qd::flatten
