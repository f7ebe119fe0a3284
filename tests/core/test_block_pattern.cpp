// lower_pattern and scalar_lower on small known graphs: the pattern holds every edge once, in
// its lower column, sorted, and nothing else; the scalar matrix is its lower triangle with the
// diagonal first; the block offsets address M's values column by column.
#include <gtest/gtest.h>

#include <set>

#include "common/block_pattern.h"
#include "solver_matrices.h"

namespace qd {
namespace {

using namespace qd::common;

std::set<std::pair<int, int>> lower_set(const test::Edges& edges) {  // (row, column), row > column
  std::set<std::pair<int, int>> s;
  for (const auto& [a, b] : edges)
    if (a != b) s.emplace(std::max(a, b), std::min(a, b));
  return s;
}

std::set<std::pair<int, int>> pattern_set(const BlockPattern& p) {
  std::set<std::pair<int, int>> s;
  for (int k = 0; k < p.blocks(); ++k)
    for (int i = p.begin(k); i < p.end(k); ++i) s.emplace(p.row(i), k);
  return s;
}

void expect_sorted_lower_columns(const BlockPattern& p) {
  for (int k = 0; k < p.blocks(); ++k)
    for (int i = p.begin(k); i < p.end(k); ++i) {
      EXPECT_GT(p.row(i), k);
      if (i > p.begin(k)) {
        EXPECT_GT(p.row(i), p.row(i - 1));
      }
    }
}

TEST(LowerPattern, HoldsEachEdgeOfAPathOnce) {
  test::Edges edges = test::path_edges(10);
  edges.emplace_back(4, 3);  // a repeat the other way round
  edges.emplace_back(6, 6);  // a self loop
  const BlockPattern p = lower_pattern(10, edges);
  EXPECT_EQ(p.blocks(), 10);
  expect_sorted_lower_columns(p);
  EXPECT_EQ(pattern_set(p), lower_set(edges));
  EXPECT_EQ(p.block_row.size(), 9u);
}

TEST(LowerPattern, KeepsTwoDisconnectedGridsApart) {
  test::Edges edges = test::grid_edges(4, 5);
  const test::Edges second = test::grid_edges(3, 3, 20);
  edges.insert(edges.end(), second.begin(), second.end());
  const BlockPattern p = lower_pattern(29, edges);
  expect_sorted_lower_columns(p);
  EXPECT_EQ(pattern_set(p), lower_set(edges));
  for (int k = 0; k < p.blocks(); ++k)
    for (int i = p.begin(k); i < p.end(k); ++i) EXPECT_EQ(p.row(i) < 20, k < 20);
}

TEST(ScalarLower, IsThePatternWithItsDiagonalFirst) {
  const test::Edges edges = test::grid_edges(3, 4);
  const BlockPattern p = lower_pattern(12, edges);
  const Eigen::SparseMatrix<double> K = scalar_lower(p);
  ASSERT_EQ(K.rows(), 12);
  EXPECT_EQ(K.nonZeros(), 12 + static_cast<Eigen::Index>(edges.size()));
  for (int k = 0; k < 12; ++k) {
    const int first = K.outerIndexPtr()[k];
    EXPECT_EQ(K.innerIndexPtr()[first], k);
    for (int e = first + 1; e < K.outerIndexPtr()[k + 1]; ++e) {
      EXPECT_EQ(K.innerIndexPtr()[e], p.row(p.begin(k) + e - first - 1));
      EXPECT_EQ(K.valuePtr()[e], 0.0);
    }
  }
}

// M's lower triangle built by Eigen from every entry of the blocks (each value its own
// (row, column) code) is read back at the offsets the pattern promises.
TEST(BlockEntries, AddressTheBlockLayoutOfM) {
  const test::Edges edges = test::grid_edges(3, 3);
  const BlockPattern p = lower_pattern(9, edges);
  const auto code = [](int row, int column) { return 1000.0 * row + column; };
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < p.blocks(); ++k)
    for (int j = 0; j < 3; ++j) {
      for (int i = j; i < 3; ++i) t.emplace_back(3 * k + i, 3 * k + j, code(3 * k + i, 3 * k + j));
      for (int s = p.begin(k); s < p.end(k); ++s)
        for (int i = 0; i < 3; ++i)
          t.emplace_back(3 * p.row(s) + i, 3 * k + j, code(3 * p.row(s) + i, 3 * k + j));
    }
  Eigen::SparseMatrix<double> M(27, 27);
  M.setFromTriplets(t.begin(), t.end());
  const int* outer = M.outerIndexPtr();
  for (int k = 0; k < p.blocks(); ++k)
    for (int j = 0; j < 3; ++j) {
      for (int i = j; i < 3; ++i)
        EXPECT_EQ(M.valuePtr()[diagonal_entry(outer, k, i, j)], code(3 * k + i, 3 * k + j));
      for (int s = p.begin(k); s < p.end(k); ++s)
        for (int i = 0; i < 3; ++i)
          EXPECT_EQ(M.valuePtr()[block_entry(outer, p, k, s, i, j)],
                    code(3 * p.row(s) + i, 3 * k + j));
    }
}

}  // namespace
}  // namespace qd
