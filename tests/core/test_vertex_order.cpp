// fill_reducing_rank on small known graphs: it is a permutation, it adds no fill to a path, and
// on grids it fills no more than the natural order; LeastFill fills no more than AMD and gives
// the same order on several threads at once as alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

#include "common/vertex_order.h"
#include "solver_matrices.h"

namespace qd {
namespace {

using namespace qd::common;

std::vector<int> natural(int n) {
  std::vector<int> rank(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) rank[static_cast<size_t>(i)] = i;
  return rank;
}

TEST(FillReducingRank, APathGetsNoFill) {
  const int n = 50;
  const std::vector<int> rank = fill_reducing_rank(n, test::path_edges(n));
  ASSERT_EQ(rank.size(), static_cast<size_t>(n));
  EXPECT_TRUE(test::is_permutation(rank));
  EXPECT_EQ(test::factor_entries(n, test::path_edges(n), rank),
            2L * n - 1);  // the diagonal and the edges
}

TEST(FillReducingRank, AGridFillsNoMoreThanTheNaturalOrder) {
  const int rows = 30, cols = 30, n = rows * cols;
  const test::Edges edges = test::grid_edges(rows, cols);
  const std::vector<int> rank = fill_reducing_rank(n, edges);
  EXPECT_TRUE(test::is_permutation(rank));
  EXPECT_LE(test::factor_entries(n, edges, rank), test::factor_entries(n, edges, natural(n)));
}

TEST(FillReducingRank, TwoDisconnectedGridsAreOrderedTogether) {
  const int n = 2 * 15 * 20;
  test::Edges edges = test::grid_edges(15, 20);
  const test::Edges second = test::grid_edges(15, 20, n / 2);
  edges.insert(edges.end(), second.begin(), second.end());
  const std::vector<int> rank = fill_reducing_rank(n, edges);
  EXPECT_TRUE(test::is_permutation(rank));
  EXPECT_LE(test::factor_entries(n, edges, rank), test::factor_entries(n, edges, natural(n)));
}

TEST(FillReducingRank, LeastFillFillsNoMoreThanMinimumDegree) {
  const int rows = 90, cols = 80, n = rows * cols;
  const test::Edges edges = test::grid_edges(rows, cols);
  const std::vector<int> least = fill_reducing_rank(n, edges, FillOrder::LeastFill);
  EXPECT_TRUE(test::is_permutation(least));
  EXPECT_LE(test::factor_entries(n, edges, least),
            test::factor_entries(n, edges, fill_reducing_rank(n, edges, FillOrder::MinimumDegree)));
}

TEST(FillReducingRank, LeastFillOrdersTheSameOnConcurrentThreads) {
  const test::Edges a = test::grid_edges(70, 60), b = test::grid_edges(50, 90);
  const std::vector<int> alone_a = fill_reducing_rank(70 * 60, a, FillOrder::LeastFill);
  const std::vector<int> alone_b = fill_reducing_rank(50 * 90, b, FillOrder::LeastFill);
  for (int round = 0; round < 10; ++round) {
    std::vector<int> at_once_a, at_once_b;
    std::thread other([&] { at_once_b = fill_reducing_rank(50 * 90, b, FillOrder::LeastFill); });
    at_once_a = fill_reducing_rank(70 * 60, a, FillOrder::LeastFill);
    other.join();
    EXPECT_EQ(at_once_a, alone_a);
    EXPECT_EQ(at_once_b, alone_b);
  }
}

TEST(FillReducingRank, IsolatedNodesAndTinyGraphs) {
  EXPECT_TRUE(fill_reducing_rank(0, {}).empty());
  EXPECT_EQ(fill_reducing_rank(1, {}), std::vector<int>{0});
  EXPECT_TRUE(test::is_permutation(fill_reducing_rank(7, {{2, 5}})));  // five nodes with no edge
}

}  // namespace
}  // namespace qd
