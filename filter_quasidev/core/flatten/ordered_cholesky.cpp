#include "flatten/ordered_cholesky.h"

#include <cassert>
#include <utility>
#include <vector>

#include "common/vertex_order.h"
#include "flatten/common_names.h"

namespace qd::flatten {
namespace {

// rank holds each of 0 … n−1 once.
[[maybe_unused]] bool is_permutation_of(const std::vector<int>& rank, Eigen::Index n) {
  std::vector<char> seen(static_cast<size_t>(n), 0);
  for (const int r : rank)
    if (r < 0 || r >= n || seen[static_cast<size_t>(r)]++) return false;
  return rank.size() == seen.size();
}

}  // namespace

OrderedCholesky::OrderedCholesky(const Eigen::SparseMatrix<double>& M, SolverKind kind,
                                 Solves solves)
    : order_(M.rows()), cholesky_(kind, solves) {
  std::vector<std::pair<int, int>> edges;
  for (int c = 0; c < M.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, c); it; ++it)
      if (it.row() > c) edges.emplace_back(static_cast<int>(it.row()), c);
  const std::vector<int> rank = fill_reducing_rank(static_cast<int>(M.rows()), edges);
  assert(is_permutation_of(rank, M.rows()));  // or the solve would not undo the order
  for (int i = 0; i < M.rows(); ++i) order_.indices()[i] = rank[i];
  Eigen::SparseMatrix<double> ordered(M.rows(), M.cols());
  ordered = M.selfadjointView<Eigen::Lower>().twistedBy(order_);
  cholesky_.factorize(ordered);
}

Eigen::MatrixXd OrderedCholesky::solve(const Eigen::MatrixXd& b) const {
  assert(b.rows() == order_.size());
  return order_.inverse() * cholesky_.solve(order_ * b);
}

}  // namespace qd::flatten
