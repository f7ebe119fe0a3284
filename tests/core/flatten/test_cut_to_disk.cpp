// Pieces of every topology come out as disks, with the cut the header promises.
#include <gtest/gtest.h>

#include "flatten/boundary_loops.h"
#include "flatten/cut_to_disk.h"
#include "flatten_meshes.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

using qd::test::GridMesh;

// The mesh as one piece (unreferenced vertices dropped).
qd::flatten::Piece piece_of(const GridMesh& m) {
  std::vector<qd::flatten::Piece> pieces = qd::flatten::extract_pieces(m.V, m.F, {});
  EXPECT_EQ(pieces.size(), 1u);
  return pieces.front();
}

void expect_disk(const qd::flatten::Piece& p) {
  const qd::flatten::EdgeTable edges = qd::flatten::edge_table(p.F, static_cast<int>(p.V.rows()));
  EXPECT_EQ(qd::flatten::boundary_loops(p.F, edges).size(), 1u);
  EXPECT_EQ(qd::flatten::euler_characteristic(p.F, edges, static_cast<int>(p.V.rows())), 1);
}

// A torus (major radius 2, minor 0.7): closed, genus 1.
GridMesh torus(int columns, int rows) {
  GridMesh m = qd::test::grid_mesh(columns, rows, true, [&](int i, int j) {
    const double t = 2 * M_PI * i / columns, s = 2 * M_PI * j / rows, r = 2 + 0.7 * std::cos(s);
    return qd::common::Vec3(r * std::cos(t), r * std::sin(t), 0.7 * std::sin(s));
  });
  // Glue the last row of vertices to the first: drop the top row.
  const int top = rows * columns;
  for (int f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (m.F(f, k) >= top) m.F(f, k) -= top;
  m.V.conservativeResize(top, 3);
  return m;
}

TEST(CutToDisk, DiskIsLeftAlone) {
  qd::flatten::Piece p = piece_of(qd::test::cylinder(8, 3, 1.0, 1.0, 2.0));
  const qd::common::Triangles before = p.F;
  const qd::flatten::DiskCut cut = qd::flatten::cut_to_disk(p);
  EXPECT_TRUE(cut.note.empty());
  EXPECT_EQ(cut.edges, 0);
  EXPECT_EQ(p.F, before);
}

TEST(CutToDisk, TubeGetsExactlyOneShortestCut) {
  qd::flatten::Piece p = piece_of(qd::test::cylinder(16, 5, 1.0, 3.0));
  const qd::flatten::DiskCut cut = qd::flatten::cut_to_disk(p);
  EXPECT_EQ(cut.joining_paths, 1);
  EXPECT_EQ(cut.handle_loops, 0);
  EXPECT_FALSE(cut.slit);
  EXPECT_EQ(cut.edges, 5);              // straight up one column of vertices
  EXPECT_NEAR(cut.length, 3.0, 1e-12);  // the height: nothing is shorter
  EXPECT_EQ(p.V.rows(), 16 * 6 + 6);
  expect_disk(p);
  // Each cut vertex has two copies of the same mesh vertex.
  std::vector<int> copies(16 * 6, 0);
  for (const int v : p.vertex) ++copies[v];
  EXPECT_EQ(std::count(copies.begin(), copies.end(), 2), 6);
}

TEST(CutToDisk, PanelWithTwoHolesGetsTwoJoiningPaths) {
  // A 12×12 grid with two 2×2 holes.
  GridMesh m =
      qd::test::grid_mesh(12, 12, false, [](int i, int j) { return qd::common::Vec3(i, j, 0); });
  std::vector<int> keep;
  for (int f = 0; f < m.F.rows(); ++f) {
    const int quad = f / 2, i = quad % 12, j = quad / 12;
    const bool hole = (j >= 3 && j < 5 && ((i >= 3 && i < 5) || (i >= 7 && i < 9)));
    if (!hole) keep.push_back(f);
  }
  qd::common::Triangles F(static_cast<int>(keep.size()), 3);
  for (size_t k = 0; k < keep.size(); ++k) F.row(static_cast<int>(k)) = m.F.row(keep[k]);
  m.F = F;
  qd::flatten::Piece p = piece_of(m);
  const qd::flatten::DiskCut cut = qd::flatten::cut_to_disk(p);
  EXPECT_EQ(cut.joining_paths, 2);
  EXPECT_NE(cut.note.find("2 shortest paths joining its 3 boundary loops"), std::string::npos)
      << cut.note;
  expect_disk(p);
}

TEST(CutToDisk, TorusGetsTwoLoops) {
  qd::flatten::Piece p = piece_of(torus(24, 12));
  const qd::flatten::DiskCut cut = qd::flatten::cut_to_disk(p);
  EXPECT_EQ(cut.handle_loops, 2);
  EXPECT_FALSE(cut.slit);
  EXPECT_NE(cut.note.find("around its 1 handle"), std::string::npos) << cut.note;
  expect_disk(p);
}

TEST(CutToDisk, TorusWithAHoleGetsTwoLoopsThroughItsBoundary) {
  GridMesh m = torus(24, 12);
  m.F = m.F.bottomRows(m.F.rows() - 4).eval();  // two quads out: one boundary loop
  qd::flatten::Piece p = piece_of(m);
  const qd::flatten::DiskCut cut = qd::flatten::cut_to_disk(p);
  EXPECT_EQ(cut.joining_paths, 0);
  EXPECT_EQ(cut.handle_loops, 2);
  expect_disk(p);
}

TEST(CutToDisk, ClosedSphereIsSlitOpen) {
  // The spherical cap up to the equator, twice (mirrored), glued along the equator.
  const GridMesh cap = qd::test::spherical_cap(16, 6, M_PI / 2);
  GridMesh sphere = cap;
  const int n = static_cast<int>(cap.V.rows());
  sphere.V.conservativeResize(2 * n, 3);
  sphere.V.bottomRows(n) = cap.V;
  sphere.V.bottomRows(n).col(2) *= -1;
  sphere.F.conservativeResize(2 * cap.F.rows(), 3);
  const int rim = 6 * 16;  // first vertex of the last ring (the equator)
  for (int f = 0; f < cap.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = cap.F(f, 2 - k);  // mirrored: reverse the orientation
      sphere.F(cap.F.rows() + f, k) = v >= rim && v < rim + 16 ? v : v + n;
    }
  qd::flatten::Piece p = piece_of(sphere);
  const qd::flatten::DiskCut cut = qd::flatten::cut_to_disk(p);
  EXPECT_TRUE(cut.slit);
  EXPECT_EQ(cut.handle_loops, 0);
  EXPECT_GT(cut.length, 2.5);  // from pole region to pole region: about π
  expect_disk(p);
}

}  // namespace
