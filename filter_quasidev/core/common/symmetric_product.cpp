#include "common/symmetric_product.h"

#include <algorithm>

#include "common/parallel_for.h"

namespace qd::common {
namespace {

// Adds the columns [first, last) of (L + Lᵀ − diag L) x to y, whose entry 0 is row `offset`
// (every row these columns touch is at least `first`).
void add_columns(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& x,
                 Eigen::Index first, Eigen::Index last, Eigen::Index offset, double* y) {
  const int* outer = lower.outerIndexPtr();
  const int* row = lower.innerIndexPtr();
  const double* value = lower.valuePtr();
  for (Eigen::Index j = first; j < last; ++j) {
    const double xj = x[j];
    double column_dot = 0;  // (Lᵀ x)_j over the entries below the diagonal
    for (int p = outer[j]; p < outer[j + 1]; ++p) {
      const Eigen::Index i = row[p];
      if (i == j) {
        y[j - offset] += value[p] * xj;
      } else {
        y[i - offset] += value[p] * xj;
        column_dot += value[p] * x[i];
      }
    }
    y[j - offset] += column_dot;
  }
}

}  // namespace

Eigen::VectorXd symmetric_product(const Eigen::SparseMatrix<double>& lower,
                                  const Eigen::VectorXd& x, int threads) {
  const Eigen::Index n = lower.cols();
  if (lower.nonZeros() < kSplitProductFromEntries || !lower.isCompressed())
    return lower.selfadjointView<Eigen::Lower>() * x;
  // The first column from which half the entries are stored: the second half touches only the
  // rows from there on.
  const int* outer = lower.outerIndexPtr();
  const Eigen::Index middle = std::upper_bound(outer, outer + n + 1, outer[n] / 2) - outer - 1;
  Eigen::VectorXd head = Eigen::VectorXd::Zero(n), tail = Eigen::VectorXd::Zero(n - middle);
  parallel_for(2, static_cast<size_t>(std::max(1, threads)), [&](size_t half) {
    if (half == 0)
      add_columns(lower, x, 0, middle, 0, head.data());
    else
      add_columns(lower, x, middle, n, middle, tail.data());
  });
  head.tail(n - middle) += tail;
  return head;
}

}  // namespace qd::common
