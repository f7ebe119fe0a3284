// The product of a symmetric sparse matrix, stored as its lower triangle, with a vector: the
// product with M inside conjugate gradients (Eq. 17 solved iteratively, issue 5).
//
// Why our own and not Eigen's selfAdjointView product: Eigen's runs on one thread. On the 1M
// family's median closed cylinder (16.4M stored entries) its 43 products took 1.39 s of a 5.3 s
// solve stage while the other core waited (docs/performance.md, stop 67).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace qd::common {

// From this many stored entries (about 32,000 vertices of M) the product is computed in two
// halves of the columns, on two threads where `threads` allows. Below it, Eigen's one pass: the
// halves' sums round differently, and this keeps the results of the garments and the
// robustness sweeps bit for bit.
constexpr long kSplitProductFromEntries = 1L << 20;

// (L + Lᵀ − diag L) x for L the lower triangle (with the diagonal) of a symmetric matrix. The
// result does not depend on `threads`: the halves and the order of their sum are fixed by L.
// An uncompressed L (room left between its columns) takes Eigen's one pass.
Eigen::VectorXd symmetric_product(const Eigen::SparseMatrix<double>& lower,
                                  const Eigen::VectorXd& x, int threads);

}  // namespace qd::common
