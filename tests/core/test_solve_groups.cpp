// Which patches are solved together (solve_groups.h): a patch joins its neighbour when holding
// its seams would keep most of what it has, its vertices or its curvature, and not otherwise.
#include <gtest/gtest.h>

#include <vector>

#include "approximate/solve_groups.h"
#include "grid_mesh.h"

namespace {

using namespace qd::approximate;

// A flat 12 × 6 grid: patch 0 the left half (columns 0-5), patch 1 the right half, so the
// seam is column 6 of vertices. Each half has 25 interior vertices of its 49: not mostly seam.
struct TwoHalves {
  qd::test::GridMesh grid =
      qd::test::grid_mesh(12, 6, false, [](int i, int j) { return qd::common::Vec3(i, j, 0); });
  std::vector<int> patch;
  std::vector<char> boundary;
  TwoHalves() {
    for (int f = 0; f < grid.F.rows(); ++f) patch.push_back((f / 2) % 12 < 6 ? 0 : 1);
    boundary.assign(static_cast<size_t>(grid.V.rows()), 0);
    for (int j = 0; j <= 6; ++j)
      for (int i = 0; i <= 12; ++i)
        boundary[static_cast<size_t>(j * 13 + i)] = i == 0 || i == 12 || j == 0 || j == 6;
  }
  // |K| = `inside` on the interior vertices off the seam, `seam` on the seam's.
  std::vector<double> curvature(double inside, double seam) const {
    std::vector<double> k(boundary.size(), 0.0);
    for (int j = 1; j < 6; ++j)
      for (int i = 1; i < 12; ++i) k[static_cast<size_t>(j * 13 + i)] = i == 6 ? seam : inside;
    return k;
  }
};

TEST(SolveGroups, PatchesWithMostOfTheirCurvatureInsideKeepTheirSeams) {
  const TwoHalves m;
  const SolveGroups s = solve_groups(m.grid.F, m.patch, m.boundary, m.curvature(1.0, 1.0)).joined;
  EXPECT_TRUE(s.joins.empty());
  EXPECT_EQ(s.group, m.patch);
}

TEST(SolveGroups, APatchWithMostOfItsCurvatureOnItsSeamJoinsItsNeighbour) {
  const TwoHalves m;
  // The 5 seam vertices off the boundary carry more than the 25 interior ones of either half.
  const SolveGroups s = solve_groups(m.grid.F, m.patch, m.boundary, m.curvature(0.1, 1.0)).joined;
  ASSERT_EQ(s.joins.size(), 1u);
  const PatchJoin& join = s.joins[0];
  EXPECT_EQ(join.faces, 72);
  EXPECT_EQ(join.reason, JoinReason::CurvatureOnSeams);
  for (size_t f = 0; f < s.group.size(); ++f) EXPECT_EQ(s.group[f], join.group);
  EXPECT_NE(join.patch, join.group);
}

// A strip one cell wide along the open boundary has no interior vertex: it joins its neighbour
// whatever the curvature, and the join says why.
TEST(SolveGroups, AStripWithNoInteriorVertexJoinsForItsSeams) {
  TwoHalves m;
  for (int f = 0; f < m.grid.F.rows(); ++f) m.patch[static_cast<size_t>(f)] = (f / 2) % 12 == 11;
  for (const std::vector<double>& k : {std::vector<double>{}, m.curvature(1.0, 0.0)}) {
    const SolveGroups s = solve_groups(m.grid.F, m.patch, m.boundary, k).joined;
    ASSERT_EQ(s.joins.size(), 1u);
    EXPECT_EQ(s.joins[0].patch, 1);
    EXPECT_EQ(s.joins[0].group, 0);
    EXPECT_EQ(s.joins[0].faces, 12);
    EXPECT_EQ(s.joins[0].reason, JoinReason::MostlySeams);
  }
}

}  // namespace
