#include "sparse_cholesky.h"

#include "error.h"

namespace qd {

void SparseCholesky::factorize(const Eigen::SparseMatrix<double>& M) {
  if (!analysed_) {
    llt_.analyzePattern(M);
    analysed_ = true;
  }
  llt_.factorize(M);
  ++factorizations_;
  if (llt_.info() != Eigen::Success)
    throw Error(
        "the deformation system is not positive definite (degenerate faces?): remove zero-area "
        "and duplicate faces, then try again");
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const { return llt_.solve(b); }

}  // namespace qd
