// coordinate_dissection and FillOrder::Coordinates (issue 28): the top separator splits a grid
// into halves and is as short as the grid's narrower side; on a closed torus the order fills no
// more than minimum degree's (the 1M-face torus of the benchmark: 28M entries against 42M,
// docs/performance.md); degenerate points and separate sheets still give a permutation, the same
// every time and on any number of threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <queue>

#include "common/block_pattern.h"
#include "common/coordinate_dissection.h"
#include "common/vertex_order.h"
#include "solver_matrices.h"

namespace qd {
namespace {

using namespace qd::common;

// A grid of rows × cols nodes, each cell split by one diagonal; closed around in both
// directions when `torus`.
test::Edges triangulated_grid(int rows, int cols, bool torus) {
  test::Edges e;
  const int last_r = torus ? rows : rows - 1, last_c = torus ? cols : cols - 1;
  auto id = [&](int r, int c) { return (r % rows) * cols + c % cols; };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      if (c < last_c) e.emplace_back(id(r, c), id(r, c + 1));
      if (r < last_r) e.emplace_back(id(r, c), id(r + 1, c));
      if (r < last_r && c < last_c) e.emplace_back(id(r, c), id(r + 1, c + 1));
    }
  return e;
}

TEST(CoordinateDissection, TheTopSeparatorHalvesAGridAlongItsNarrowerSide) {
  const int rows = 40, cols = 60, n = rows * cols;
  const test::Edges edges = triangulated_grid(rows, cols, false);
  std::vector<Vec3> points;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) points.emplace_back(c, r, 0.0);
  const std::vector<int> set = coordinate_dissection(lower_pattern(n, edges), points, 100);
  const int top = *std::max_element(set.begin(), set.end());
  const long separator = std::count(set.begin(), set.end(), top);
  EXPECT_GE(separator, rows / 2);
  EXPECT_LE(separator, rows);  // a column, not a row of 60
  // Without the separator, no part holds more than half of the nodes.
  std::vector<std::vector<int>> adjacent(static_cast<size_t>(n));
  for (const auto& [a, b] : edges) {
    adjacent[static_cast<size_t>(a)].push_back(b);
    adjacent[static_cast<size_t>(b)].push_back(a);
  }
  std::vector<char> seen(static_cast<size_t>(n), 0);
  int parts = 0;
  for (int s = 0; s < n; ++s) {
    if (seen[static_cast<size_t>(s)] || set[static_cast<size_t>(s)] == top) continue;
    ++parts;
    long size = 0;
    std::queue<int> queue;
    queue.push(s);
    seen[static_cast<size_t>(s)] = 1;
    while (!queue.empty()) {
      const int v = queue.front();
      queue.pop();
      ++size;
      for (int w : adjacent[static_cast<size_t>(v)])
        if (!seen[static_cast<size_t>(w)] && set[static_cast<size_t>(w)] != top) {
          seen[static_cast<size_t>(w)] = 1;
          queue.push(w);
        }
    }
    EXPECT_LE(size, n / 2);
  }
  EXPECT_EQ(parts, 2);
}

TEST(CoordinateDissection, ATorusFillsNoMoreThanUnderMinimumDegree) {
  const int around = 240, tube = 120, n = around * tube;
  const test::Edges edges = triangulated_grid(tube, around, true);
  std::vector<Vec3> points;
  const double pi = std::acos(-1.0);
  for (int j = 0; j < tube; ++j)
    for (int i = 0; i < around; ++i) {
      const double u = 2 * pi * i / around, v = 2 * pi * j / tube, r = 2.0 + std::cos(v);
      points.emplace_back(r * std::cos(u), r * std::sin(u), std::sin(v));
    }
  const std::vector<int> rank = fill_reducing_rank(lower_pattern(n, edges), points, 500);
  ASSERT_TRUE(test::is_permutation(rank));
  const long dissected = test::factor_entries(n, edges, rank);
  const long minimum_degree = test::factor_entries(n, edges, fill_reducing_rank(n, edges));
  EXPECT_LE(dissected, minimum_degree);
}

TEST(CoordinateDissection, EqualPointsStillGiveTheSamePermutation) {
  const int rows = 50, cols = 50, n = rows * cols;
  const test::Edges edges = triangulated_grid(rows, cols, false);
  const std::vector<Vec3> points(static_cast<size_t>(n), Vec3(1.0, 2.0, 3.0));
  const BlockPattern graph = lower_pattern(n, edges);
  const std::vector<int> rank = fill_reducing_rank(graph, points, 64);
  EXPECT_TRUE(test::is_permutation(rank));
  EXPECT_EQ(fill_reducing_rank(graph, points, 64), rank);
  const std::vector<int> set = coordinate_dissection(graph, points, 64);
  EXPECT_EQ(coordinate_dissection(graph, points, 64), set);
}

TEST(CoordinateDissection, TwoSeparateSheetsGiveAPermutationOnTwoThreads) {
  const int side = 40, n = 2 * side * side;
  test::Edges edges = triangulated_grid(side, side, false);
  for (const auto& [a, b] : triangulated_grid(side, side, false))
    edges.emplace_back(a + n / 2, b + n / 2);
  std::vector<Vec3> points;
  for (int sheet = 0; sheet < 2; ++sheet)
    for (int r = 0; r < side; ++r)
      for (int c = 0; c < side; ++c) points.emplace_back(c, r, 5.0 * sheet);
  const BlockPattern graph = lower_pattern(n, edges);
  const std::vector<int> alone = fill_reducing_rank(graph, points, 100, 1);
  EXPECT_TRUE(test::is_permutation(alone));
  EXPECT_EQ(fill_reducing_rank(graph, points, 100, 2), alone);
}

}  // namespace
}  // namespace qd
