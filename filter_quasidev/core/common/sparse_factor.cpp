#include "common/sparse_factor.h"

#include <string>

#include "common/error.h"

namespace qd::common {

SparseFactor::~SparseFactor() = default;

void SparseFactor::factorize(const Eigen::SparseMatrix<double>& lower) {
  if (!backend_) {
    const Choice choice = choose(lower.rows());
    backend_ = make(choice.kind);
    backend_kind_ = choice.kind;
    substituted_ = choice.substituted;
  }
  const bool ok = backend_->analyse_and_factorize(lower, factorizations_ == 0);
  ++factorizations_;
  flops_ += backend_->flops;
  if (!ok)
    throw Error(std::string("the deformation system ") + failure() +
                " (degenerate faces?): remove zero-area and duplicate faces, then try again");
}

void SparseFactor::count_columns(const Eigen::SparseMatrix<double>& L, Backend& counts) {
  counts.flops = counts.entries = 0;
  for (Eigen::Index j = 0; j < L.outerSize(); ++j) {
    double c = 1;  // the diagonal, whether L stores it (LLᵀ) or not (LDLᵀ)
    for (Eigen::SparseMatrix<double>::InnerIterator it(L, j); it; ++it) c += it.row() > j;
    counts.flops += c * c;
    counts.entries += c;
  }
}

void SparseFactor::throw_no_cholmod() {
  throw Error("this build of the engine has no CHOLMOD: choose the eigen-llt or eigen-ldlt solver");
}

Eigen::MatrixXd SparseFactor::solve(const Eigen::MatrixXd& b) const { return backend_->solve(b); }

}  // namespace qd::common
