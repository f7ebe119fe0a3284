// Developable patches with known developments flatten to them: edge lengths and area to 0.1 %.
#include <gtest/gtest.h>

#include "flatten/flatten.h"
#include "flatten_meshes.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

using qd::test::GridMesh;

// Largest relative error of an edge length on the pattern against 3D, over every face.
double max_edge_error(const GridMesh& m, const qd::flatten::FlattenResult& r) {
  double worst = 0;
  for (int f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int l = (k + 1) % 3;
      const double d3 = (m.V.row(m.F(f, k)) - m.V.row(m.F(f, l))).norm();
      const double d2 = (r.uv.block<1, 2>(f, 2 * k) - r.uv.block<1, 2>(f, 2 * l)).norm();
      worst = std::max(worst, std::abs(d2 - d3) / d3);
    }
  return worst;
}

qd::flatten::FlattenResult run(const GridMesh& m) {
  qd::flatten::FlattenProblem p;
  p.V = m.V;
  p.F = m.F;
  p.patch = m.patch;
  return qd::flatten::flatten(p);
}

TEST(FlattenExact, CylinderTubeCutOnceFlattensToItsRectangle) {
  const GridMesh m = qd::test::cylinder(32, 8, 1.0, 2.0);
  const qd::flatten::FlattenResult r = run(m);
  ASSERT_EQ(r.pieces.size(), 1u);
  const qd::flatten::PieceReport& p = r.pieces[0];
  EXPECT_LT(max_edge_error(m, r), 1e-3);
  EXPECT_LT(std::abs(p.area_change), 0.1);
  EXPECT_EQ(p.flipped, 0);
  EXPECT_EQ(p.overlapping, 0);
  EXPECT_TRUE(p.flattenable);
  EXPECT_NE(p.cut.find("1 shortest path joining its 2 boundary loops"), std::string::npos) << p.cut;
  EXPECT_EQ(p.vertices, 32 * 9 + 9);  // one column of 9 vertices duplicated
  const Eigen::Vector2d size = p.box.sizes();
  const double width = 32 * 2 * std::sin(M_PI / 32);
  EXPECT_NEAR(std::max(size.x(), size.y()), width, 1e-3 * width);
  EXPECT_NEAR(std::min(size.x(), size.y()), 2.0, 2e-3);
}

TEST(FlattenExact, ConeTubeFlattensToItsSector) {
  const GridMesh m = qd::test::cone(40, 10, 1.0, 0.4, 1.5);
  const qd::flatten::FlattenResult r = run(m);
  ASSERT_EQ(r.pieces.size(), 1u);
  const qd::flatten::PieceReport& p = r.pieces[0];
  EXPECT_LT(max_edge_error(m, r), 1e-3);
  EXPECT_LT(std::abs(p.area_change), 0.1);
  EXPECT_LT(std::abs(p.boundary_change), 0.1);
  EXPECT_EQ(p.flipped, 0);
  EXPECT_EQ(p.overlapping, 0);
  EXPECT_NE(p.cut.find("1 shortest path"), std::string::npos) << p.cut;
}

// The boundary-first start alone (no ARAP iteration) is already the development.
TEST(FlattenExact, TheStartIsTheDevelopmentAlready) {
  for (const GridMesh& m :
       {qd::test::cylinder(32, 8, 1.0, 2.0), qd::test::cone(40, 10, 1.0, 0.4, 1.5)}) {
    qd::flatten::FlattenProblem p;
    p.V = m.V;
    p.F = m.F;
    p.params.max_iterations = 0;
    const qd::flatten::FlattenResult r = qd::flatten::flatten(p);
    EXPECT_EQ(r.pieces[0].iterations, 0);
    EXPECT_LT(max_edge_error(m, r), 1e-9);
  }
}

// Open strips need no cut; the pattern is the same rectangle / sector, at true scale.
TEST(FlattenExact, OpenCylinderAndConeStripsNeedNoCut) {
  for (const GridMesh& m :
       {qd::test::cylinder(24, 6, 2.0, 1.0, 2.5), qd::test::cone(24, 6, 2.0, 0.5, 1.0, 3.0)}) {
    const qd::flatten::FlattenResult r = run(m);
    ASSERT_EQ(r.pieces.size(), 1u);
    EXPECT_TRUE(r.pieces[0].cut.empty()) << r.pieces[0].cut;
    EXPECT_LT(max_edge_error(m, r), 1e-6);
    EXPECT_LT(std::abs(r.pieces[0].area_change), 1e-4);
    EXPECT_EQ(r.pieces[0].flipped, 0);
    EXPECT_EQ(r.pieces[0].overlapping, 0);
  }
}

}  // namespace
