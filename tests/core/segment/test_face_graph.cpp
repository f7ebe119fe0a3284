// The face graph: symmetric neighbours across manifold edges, and borders at open boundaries,
// non-manifold edges, inconsistent orientation, region changes and creases; the topology of
// patches (boundary loops, Euler characteristic, disks).
#include <gtest/gtest.h>

#include "segment/face_graph.h"
#include "segment/face_parts.h"
#include "segment/patch_topology.h"
#include "segment_meshes.h"

namespace qd::test {
namespace {

using namespace qd::common;
using namespace qd::segment;

FaceGraph graph_of(const SegmentProblem& p, const std::vector<int>& region = {}) {
  return face_graph(p.V, p.F, region);
}

TEST(FaceGraph, NeighboursAreSymmetricAndShareTheSide) {
  const SegmentProblem p = cube(4).problem();
  const FaceGraph graph = graph_of(p);
  for (int f = 0; f < p.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int h = graph.neighbour[f][k];
      ASSERT_GE(h, 0) << "a closed mesh has a neighbour on every side";
      const int a = p.F(f, k), b = p.F(f, (k + 1) % 3);
      int back = 0;
      for (int j = 0; j < 3; ++j)
        if (graph.neighbour[h][j] == f) {
          ++back;
          EXPECT_EQ(p.F(h, j), b);  // h runs along the side the other way
          EXPECT_EQ(p.F(h, (j + 1) % 3), a);
        }
      EXPECT_EQ(back, 1);
    }
  EXPECT_EQ(graph.nonmanifold_edges, 0);
  EXPECT_EQ(graph.misoriented_edges, 0);
}

TEST(FaceGraph, CreasesCutTheCubeIntoItsSides) {
  const SegmentProblem p = cube(4).problem();
  FaceGraph graph = graph_of(p);
  const FaceGeometry g = face_geometry(p.V, p.F, 1);
  EXPECT_EQ(connected_parts(graph, std::vector<int>(p.F.rows(), 0)).count, 1);
  remove_creases(graph, g, 60 * M_PI / 180);
  EXPECT_EQ(graph.creases.size(), 12u * 4);  // 12 cube edges of 4 mesh edges each
  EXPECT_EQ(connected_parts(graph, std::vector<int>(p.F.rows(), 0)).count, 6);
}

TEST(FaceGraph, NonManifoldEdgesAreBorders) {
  const SegmentProblem p = book(3).problem();
  const FaceGraph graph = graph_of(p);
  EXPECT_EQ(graph.nonmanifold_edges, 3);  // the spine's three edges
  EXPECT_EQ(connected_parts(graph, std::vector<int>(p.F.rows(), 0)).count, 3);
}

TEST(FaceGraph, MisorientedEdgesAndRegionChangesAreBorders) {
  SegmentProblem p = bumped_plane(4, 0.0).problem();
  const int flipped = 0;
  std::swap(p.F(flipped, 1), p.F(flipped, 2));
  const FaceGraph graph = graph_of(p);
  EXPECT_GE(graph.misoriented_edges, 1);
  for (const int h : graph.neighbour[flipped]) EXPECT_EQ(h, -1);

  SegmentProblem q = bumped_plane(4, 0.0).problem();
  std::vector<int> region(q.F.rows(), 0);
  for (int f = 0; f < 8; ++f) region[f] = 1;  // the first row of quads
  const FaceGraph split = graph_of(q, region);
  EXPECT_EQ(split.region_edges, 4);
  EXPECT_EQ(connected_parts(split, region).count, 2);
}

TEST(PatchTopology, DiscsAnnulusAndClosedSurface) {
  const MeshBuilder b = capped_cylinder(16, 4, 3);
  const SegmentProblem p = b.problem();
  const std::vector<PatchTopology> t = patch_topology(p.F, p.V.rows(), b.pieces(), 3);
  EXPECT_EQ(t[0].boundary_loops, 2);  // the side: an annulus
  EXPECT_EQ(t[0].euler(), 0);
  EXPECT_FALSE(t[0].disk());
  for (const int disc : {1, 2}) {
    EXPECT_EQ(t[disc].boundary_loops, 1);
    EXPECT_EQ(t[disc].euler(), 1);
    EXPECT_TRUE(t[disc].disk());
  }
  const std::vector<PatchTopology> whole =
      patch_topology(p.F, p.V.rows(), std::vector<int>(p.F.rows(), 0), 1);
  EXPECT_EQ(whole[0].boundary_loops, 0);
  EXPECT_EQ(whole[0].euler(), 2);  // a sphere
  EXPECT_EQ(whole[0].faces, p.F.rows());
}

}  // namespace
}  // namespace qd::test
