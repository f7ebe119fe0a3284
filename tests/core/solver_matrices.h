// Small matrices with known structure for the solver tests: graphs (a path, a grid, two
// disconnected grids), their Laplacians, and random quasi-definite systems; and what the
// order tests measure of an order: that it is a permutation, and its factor's entries.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "common/block_pattern.h"
#include "common/mesh.h"

namespace qd::test {

using namespace qd::common;

using Edges = std::vector<std::pair<int, int>>;

inline Edges path_edges(int n) {
  Edges e;
  for (int i = 0; i + 1 < n; ++i) e.emplace_back(i, i + 1);
  return e;
}

// rows × cols nodes, numbered row by row, joined to their right and lower neighbours; the first
// node is `offset`.
inline Edges grid_edges(int rows, int cols, int offset = 0) {
  Edges e;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const int v = offset + r * cols + c;
      if (c + 1 < cols) e.emplace_back(v, v + 1);
      if (r + 1 < rows) e.emplace_back(v, v + cols);
    }
  return e;
}

// Lower triangle of the graph Laplacian plus `shift` times the identity (SPD for shift > 0).
inline Eigen::SparseMatrix<double> laplacian_lower(int n, const Edges& edges, double shift) {
  std::vector<Eigen::Triplet<double>> t;
  std::vector<double> degree(static_cast<size_t>(n), shift);
  for (const auto& [a, b] : edges) {
    t.emplace_back(std::max(a, b), std::min(a, b), -1.0);
    degree[static_cast<size_t>(a)] += 1, degree[static_cast<size_t>(b)] += 1;
  }
  for (int i = 0; i < n; ++i) t.emplace_back(i, i, degree[static_cast<size_t>(i)]);
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(t.begin(), t.end());
  return L;
}

// Lower triangle of K = [[A, Bᵀ], [B, −C]] (A: a×a and C: c×c SPD, made so by diagonal
// dominance; B sparse random), symmetrically permuted at random so that the negative pivots
// are spread among the positive ones. `per_column`: random off-diagonal entries per column.
inline Eigen::SparseMatrix<double> random_quasi_definite(int a, int c, int per_column,
                                                         unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  const int n = a + c;
  std::vector<int> perm(static_cast<size_t>(n));
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  std::vector<Eigen::Triplet<double>> t;
  std::vector<double> dominance(static_cast<size_t>(n), 1.0);
  const auto add = [&](int i, int j, double v) {  // block-local (i, j), i ≠ j, and its mirror
    dominance[static_cast<size_t>(i)] += std::abs(v),
        dominance[static_cast<size_t>(j)] += std::abs(v);
    const int pi = perm[static_cast<size_t>(i)], pj = perm[static_cast<size_t>(j)];
    t.emplace_back(std::max(pi, pj), std::min(pi, pj), v);
  };
  std::uniform_int_distribution<int> in_a(0, a - 1), in_c(a, n - 1);
  for (int j = 0; j < a; ++j)
    for (int k = 0; k < per_column; ++k) {
      const int i = in_a(rng);
      if (i != j) add(i, j, value(rng));  // A
      add(in_c(rng), j, value(rng));      // B
    }
  for (int j = a; j < n; ++j) {
    const int i = in_c(rng);
    if (i != j) add(i, j, value(rng));  // C
  }
  for (int i = 0; i < n; ++i)
    t.emplace_back(perm[static_cast<size_t>(i)], perm[static_cast<size_t>(i)],
                   (i < a ? 1.0 : -1.0) * dominance[static_cast<size_t>(i)]);
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

// M's lower triangle in the BlockPattern layout: block (r, k) = a_rk·N + b_rk·(I − N) + c·S,
// with a and b the grid's shifted Laplacians, N = ννᵀ and S a fixed symmetric coupling.
inline Eigen::SparseMatrix<double> block_matrix(const BlockPattern& p, const Edges& edges,
                                                const Vec3& nu, double stiff, double shift,
                                                double coupling) {
  const int n = p.blocks();
  const Eigen::SparseMatrix<double> L = laplacian_lower(n, edges, shift);
  const Eigen::Matrix3d N = nu.normalized() * nu.normalized().transpose();
  Eigen::Matrix3d S;
  S << 0, 1, 0, 1, 0, 1, 0, 1, 0;
  const auto block = [&](double l) -> Eigen::Matrix3d {
    return stiff * l * N + l * (Eigen::Matrix3d::Identity() - N) + coupling * l * S;
  };
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < n; ++k) {
    const Eigen::Matrix3d D = block(L.coeff(k, k));
    for (int j = 0; j < 3; ++j)
      for (int i = j; i < 3; ++i) t.emplace_back(3 * k + i, 3 * k + j, D(i, j));
    for (int s = p.begin(k); s < p.end(k); ++s) {
      const Eigen::Matrix3d B = block(L.coeff(p.row(s), k));
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) t.emplace_back(3 * p.row(s) + i, 3 * k + j, B(i, j));
    }
  }
  Eigen::SparseMatrix<double> M(3 * n, 3 * n);
  M.setFromTriplets(t.begin(), t.end());
  return M;
}

// rank holds every position 0..n-1 once.
inline bool is_permutation(std::vector<int> rank) {
  std::sort(rank.begin(), rank.end());
  for (size_t i = 0; i < rank.size(); ++i)
    if (rank[i] != static_cast<int>(i)) return false;
  return true;
}

// Entries of the Cholesky factor of the graph's shifted Laplacian with node v numbered rank[v]
// (a test failure, and 0, if it cannot be factorised).
inline long factor_entries(int n, const Edges& edges, const std::vector<int>& rank) {
  Edges ranked;
  for (const auto& [a, b] : edges)
    ranked.emplace_back(rank[static_cast<size_t>(a)], rank[static_cast<size_t>(b)]);
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> llt(
      laplacian_lower(n, ranked, 1.0));
  if (llt.info() != Eigen::Success) {
    ADD_FAILURE() << "the shifted Laplacian could not be factorised";
    return 0;
  }
  const Eigen::SparseMatrix<double> L = llt.matrixL();
  return L.nonZeros();
}

}  // namespace qd::test
