// Boundary, seams, used vertices and non-manifold elements of small hand-built meshes.
#include <gtest/gtest.h>

#include "common/topology.h"

namespace {

using namespace qd::common;

// 3×3 grid of vertices (index = 3·row + column), 2×2 quads split into 8 faces; the left quad
// column is patch 0, the right one patch 1. Vertex 9 is isolated.
struct TwoPatchGrid {
  qd::common::Triangles F{8, 3};
  std::vector<int> patch;
  TwoPatchGrid() {
    int f = 0;
    for (int r = 0; r < 2; ++r) {
      for (int c = 0; c < 2; ++c) {
        const int a = 3 * r + c;
        F.row(f++) << a, a + 1, a + 4;
        F.row(f++) << a, a + 4, a + 3;
        patch.push_back(c);
        patch.push_back(c);
      }
    }
  }
};

TEST(Topology, TwoPatchGridSeamsAndBoundary) {
  const TwoPatchGrid g;
  const qd::common::Topology t = qd::common::analyse_topology(g.F, 10, g.patch);
  for (int v = 0; v < 9; ++v) {
    EXPECT_TRUE(t.used[v]) << v;
    EXPECT_EQ(t.boundary[v] != 0, v != 4) << v;
    EXPECT_EQ(t.seam[v] != 0, v % 3 == 1) << v;
  }
  EXPECT_FALSE(t.used[9]);
  EXPECT_FALSE(t.boundary[9]);
  EXPECT_FALSE(t.seam[9]);
  EXPECT_EQ(t.nonmanifold_edges, 0);
  EXPECT_EQ(t.nonmanifold_vertices, 0);
  EXPECT_EQ(t.first_nonmanifold_vertex, -1);
}

TEST(Topology, NoPatchesMeansNoSeams) {
  const TwoPatchGrid g;
  const qd::common::Topology t = qd::common::analyse_topology(g.F, 9, {});
  for (int v = 0; v < 9; ++v) EXPECT_FALSE(t.seam[v]) << v;
}

TEST(Topology, ThreeFacesOnOneEdgeIsNonManifold) {
  qd::common::Triangles F(3, 3);
  F << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  const qd::common::Topology t = qd::common::analyse_topology(F, 5, {});
  EXPECT_EQ(t.nonmanifold_edges, 1);
  EXPECT_EQ(t.first_nonmanifold_edge[0], 0);
  EXPECT_EQ(t.first_nonmanifold_edge[1], 1);
  // Edge 0–1 has three faces, so it is no boundary edge; the outer edges are.
  for (int v = 0; v < 5; ++v) EXPECT_TRUE(t.boundary[v]) << v;
}

TEST(Topology, BowTieVertexIsNonManifold) {
  qd::common::Triangles F(2, 3);
  F << 0, 1, 2, 0, 3, 4;
  const qd::common::Topology t = qd::common::analyse_topology(F, 5, {});
  EXPECT_EQ(t.nonmanifold_vertices, 1);
  EXPECT_EQ(t.first_nonmanifold_vertex, 0);
  EXPECT_EQ(t.nonmanifold_edges, 0);
}

TEST(Topology, ClosedFanIsManifoldAndHasNoBoundary) {
  // Tetrahedron: closed, every vertex one fan.
  qd::common::Triangles F(4, 3);
  F << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  const qd::common::Topology t = qd::common::analyse_topology(F, 4, {});
  EXPECT_EQ(t.nonmanifold_vertices, 0);
  EXPECT_EQ(t.nonmanifold_edges, 0);
  for (int v = 0; v < 4; ++v) EXPECT_FALSE(t.boundary[v]) << v;
}

}  // namespace
