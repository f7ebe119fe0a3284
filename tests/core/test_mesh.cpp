// Face normal, face area and average edge length on tiny meshes with known answers.
#include <gtest/gtest.h>

#include <cmath>

#include "common/mesh.h"

namespace {

qd::Positions unit_square() {
  qd::Positions V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  return V;
}

qd::Triangles square_faces() {
  qd::Triangles F(2, 3);
  F << 0, 1, 2, 0, 2, 3;
  return F;
}

TEST(Mesh, NormalFollowsOrientation) {
  const qd::Positions V = unit_square();
  qd::Triangles F(2, 3);
  F << 0, 1, 2, 0, 2, 1;
  EXPECT_TRUE(qd::face_normal(V, F, 0).isApprox(qd::Vec3(0, 0, 1)));
  EXPECT_TRUE(qd::face_normal(V, F, 1).isApprox(qd::Vec3(0, 0, -1)));
}

TEST(Mesh, NormalOfTiltedFaceIsUnit) {
  qd::Positions V(3, 3);
  V << 0, 0, 0, 2, 0, 2, 0, 3, 0;
  qd::Triangles F(1, 3);
  F << 0, 1, 2;
  const qd::Vec3 n = qd::face_normal(V, F, 0);
  EXPECT_NEAR(n.norm(), 1.0, 1e-15);
  EXPECT_TRUE(n.isApprox(qd::Vec3(-1, 0, 1) / std::sqrt(2.0)));
}

TEST(Mesh, ZeroAreaFaceHasZeroNormalAndArea) {
  qd::Positions V(3, 3);
  V << 0, 0, 0, 1, 1, 1, 2, 2, 2;  // collinear
  qd::Triangles F(1, 3);
  F << 0, 1, 2;
  EXPECT_EQ(qd::face_normal(V, F, 0), qd::Vec3::Zero());
  EXPECT_EQ(qd::face_area(V, F, 0), 0.0);
}

TEST(Mesh, AreaOfRightTriangle) {
  qd::Positions V(3, 3);
  V << 0, 0, 0, 2, 0, 0, 0, 3, 0;
  qd::Triangles F(1, 3);
  F << 0, 1, 2;
  EXPECT_DOUBLE_EQ(qd::face_area(V, F, 0), 3.0);
}

TEST(Mesh, AverageEdgeCountsSharedEdgeOnce) {
  const qd::Positions V = unit_square();
  const qd::Triangles F = square_faces();
  // Four sides of length 1 and the diagonal once.
  EXPECT_DOUBLE_EQ(qd::average_edge_length(V, F), (4.0 + std::sqrt(2.0)) / 5.0);
  EXPECT_DOUBLE_EQ(qd::average_edge_length(V, F, {1}), (2.0 + std::sqrt(2.0)) / 3.0);
}

TEST(Mesh, AverageEdgeScalesWithMesh) {
  const qd::Triangles F = square_faces();
  const qd::Positions V = unit_square();
  const qd::Positions scaled = 7.5 * V;
  EXPECT_NEAR(qd::average_edge_length(scaled, F), 7.5 * qd::average_edge_length(V, F), 1e-12);
}

}  // namespace
