// Face normal, face area and average edge length on tiny meshes with known answers.
#include <gtest/gtest.h>

#include <cmath>

#include "common/mesh.h"

namespace {

using namespace qd::common;

qd::common::Positions unit_square() {
  qd::common::Positions V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  return V;
}

qd::common::Triangles square_faces() {
  qd::common::Triangles F(2, 3);
  F << 0, 1, 2, 0, 2, 3;
  return F;
}

TEST(Mesh, NormalFollowsOrientation) {
  const qd::common::Positions V = unit_square();
  qd::common::Triangles F(2, 3);
  F << 0, 1, 2, 0, 2, 1;
  EXPECT_TRUE(qd::common::face_normal(V, F, 0).isApprox(qd::common::Vec3(0, 0, 1)));
  EXPECT_TRUE(qd::common::face_normal(V, F, 1).isApprox(qd::common::Vec3(0, 0, -1)));
}

TEST(Mesh, NormalOfTiltedFaceIsUnit) {
  qd::common::Positions V(3, 3);
  V << 0, 0, 0, 2, 0, 2, 0, 3, 0;
  qd::common::Triangles F(1, 3);
  F << 0, 1, 2;
  const qd::common::Vec3 n = qd::common::face_normal(V, F, 0);
  EXPECT_NEAR(n.norm(), 1.0, 1e-15);
  EXPECT_TRUE(n.isApprox(qd::common::Vec3(-1, 0, 1) / std::sqrt(2.0)));
}

TEST(Mesh, ZeroAreaFaceHasZeroNormalAndArea) {
  qd::common::Positions V(3, 3);
  V << 0, 0, 0, 1, 1, 1, 2, 2, 2;  // collinear
  qd::common::Triangles F(1, 3);
  F << 0, 1, 2;
  EXPECT_EQ(qd::common::face_normal(V, F, 0), qd::common::Vec3::Zero());
  EXPECT_EQ(qd::common::face_area(V, F, 0), 0.0);
}

TEST(Mesh, AreaOfRightTriangle) {
  qd::common::Positions V(3, 3);
  V << 0, 0, 0, 2, 0, 0, 0, 3, 0;
  qd::common::Triangles F(1, 3);
  F << 0, 1, 2;
  EXPECT_DOUBLE_EQ(qd::common::face_area(V, F, 0), 3.0);
}

TEST(Mesh, AverageEdgeCountsSharedEdgeOnce) {
  const qd::common::Positions V = unit_square();
  const qd::common::Triangles F = square_faces();
  // Four sides of length 1 and the diagonal once.
  EXPECT_DOUBLE_EQ(qd::common::average_edge_length(V, F), (4.0 + std::sqrt(2.0)) / 5.0);
  EXPECT_DOUBLE_EQ(qd::common::average_edge_length(V, F, {1}), (2.0 + std::sqrt(2.0)) / 3.0);
}

TEST(Mesh, AverageEdgeScalesWithMesh) {
  const qd::common::Triangles F = square_faces();
  const qd::common::Positions V = unit_square();
  const qd::common::Positions scaled = 7.5 * V;
  EXPECT_NEAR(qd::common::average_edge_length(scaled, F),
              7.5 * qd::common::average_edge_length(V, F), 1e-12);
}

}  // namespace
