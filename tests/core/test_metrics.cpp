// Angle defect, mixed area, K(v), OBD, shape difference and measure() against values
// worked out by hand on tiny meshes.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "common/metrics.h"
#include "common/topology.h"

namespace {

using namespace qd::common;

const double kPi = std::acos(-1.0);

qd::common::Triangles one_face() {
  qd::common::Triangles F(1, 3);
  F << 0, 1, 2;
  return F;
}

// Vertex 0 at the origin with the three unit-square faces of a cube corner around it.
void cube_corner(qd::common::Positions& V, qd::common::Triangles& F) {
  V.resize(4, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  F.resize(3, 3);
  F << 0, 1, 2, 0, 2, 3, 0, 3, 1;
}

std::vector<char> only(int v, int n) {
  std::vector<char> flags(n, 0);
  flags[v] = 1;
  return flags;
}

TEST(Metrics, CubeCornerDefectAndCurvature) {
  qd::common::Positions V;
  qd::common::Triangles F;
  cube_corner(V, F);
  // Three right angles: defect 2π − 3π/2 = π/2. Each right isosceles face gives the corner
  // 1/8·(1·cot 45° + 1·cot 45°) = 1/4, so A = 3/4 and K = (π/2)/(3/4).
  EXPECT_NEAR(qd::common::vertex_angles(V, F).defect[0], kPi / 2, 1e-12);
  EXPECT_NEAR(qd::common::vertex_angles(V, F).area[0], 0.75, 1e-12);
  const std::vector<double> k =
      qd::common::gaussian_curvature(qd::common::vertex_angles(V, F), only(0, 4));
  EXPECT_NEAR(k[0], 2 * kPi / 3, 1e-12);
  EXPECT_EQ(k[1], 0.0);  // not flagged interior
}

TEST(Metrics, FanWithObtuseFaces) {
  // Around the origin: X, Y at unit distance, W = (−1, −1, √2) at distance 2. Angles at 0:
  // XOY = 90°, YOW = WOX = 120° (cos = −1/2), so the defect is 360° − 330° = π/6.
  qd::common::Positions V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, -1, std::sqrt(2.0);
  qd::common::Triangles F(3, 3);
  F << 0, 1, 2, 0, 2, 3, 0, 3, 1;
  // Mixed area: 1/4 from the right face; the two obtuse faces (area ½·1·2·sin 120° = √3/2)
  // give their obtuse corner half their area each.
  const double area = 0.25 + std::sqrt(3.0) / 2;
  EXPECT_NEAR(qd::common::vertex_angles(V, F).defect[0], kPi / 6, 1e-12);
  EXPECT_NEAR(qd::common::vertex_angles(V, F).area[0], area, 1e-12);
  EXPECT_NEAR(qd::common::gaussian_curvature(qd::common::vertex_angles(V, F), only(0, 4))[0],
              (kPi / 6) / area, 1e-12);
  // W is an acute corner of both obtuse faces: a quarter of each.
  EXPECT_NEAR(qd::common::vertex_angles(V, F).area[3], std::sqrt(3.0) / 4, 1e-12);
}

TEST(Metrics, MixedAreaRulesOnSingleTriangles) {
  const qd::common::Triangles F = one_face();
  qd::common::Positions obtuse(3, 3);
  obtuse << 0, 0, 0, 4, 0, 0, 2, 0.5, 0;  // area 1, obtuse at vertex 2
  std::vector<double> a = qd::common::vertex_angles(obtuse, F).area;
  EXPECT_NEAR(a[0], 0.25, 1e-14);
  EXPECT_NEAR(a[1], 0.25, 1e-14);
  EXPECT_NEAR(a[2], 0.5, 1e-14);

  qd::common::Positions right(3, 3);
  right << 0, 0, 0, 1, 0, 0, 0, 1, 0;  // right angle at 0: Voronoi rule, cot 90° = 0
  a = qd::common::vertex_angles(right, F).area;
  EXPECT_NEAR(a[0], 0.25, 1e-14);
  EXPECT_NEAR(a[1], 0.125, 1e-14);
  EXPECT_NEAR(a[2], 0.125, 1e-14);

  qd::common::Positions equilateral(3, 3);
  equilateral << 0, 0, 0, 1, 0, 0, 0.5, std::sqrt(3.0) / 2, 0;
  a = qd::common::vertex_angles(equilateral, F).area;
  for (int v = 0; v < 3; ++v) EXPECT_NEAR(a[v], std::sqrt(3.0) / 12, 1e-14);
}

TEST(Metrics, HexagonalPyramidApexMatchesClosedForm) {
  const double h = 0.7;
  qd::common::Positions V(7, 3);
  V.row(0) << 0, 0, h;
  qd::common::Triangles F(6, 3);
  for (int i = 0; i < 6; ++i) {
    V.row(i + 1) << std::cos(kPi * i / 3), std::sin(kPi * i / 3), 0;
    F.row(i) << 0, i + 1, (i + 1) % 6 + 1;
  }
  // Isosceles faces: legs L, base 1, apex angle θ, base angles β; all acute.
  const double L = std::sqrt(1 + h * h);
  const double theta = 2 * std::asin(0.5 / L);
  const double beta = (kPi - theta) / 2;
  const double defect = 2 * kPi - 6 * theta;
  const double area = 6 * (L * L / std::tan(beta)) / 4;
  EXPECT_NEAR(qd::common::vertex_angles(V, F).defect[0], defect, 1e-12);
  EXPECT_NEAR(qd::common::vertex_angles(V, F).area[0], area, 1e-12);
  EXPECT_NEAR(qd::common::gaussian_curvature(qd::common::vertex_angles(V, F), only(0, 7))[0],
              defect / area, 1e-12);
}

// 5×5 grid in a tilted plane, inner vertices shifted within the plane.
void flat_grid(qd::common::Positions& V, qd::common::Triangles& F) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, qd::common::Vec3(1, 2, 3).normalized()).matrix();
  V.resize(25, 3);
  for (int r = 0; r < 5; ++r) {
    for (int c = 0; c < 5; ++c) {
      const bool inner = r > 0 && r < 4 && c > 0 && c < 4;
      const double dx = inner ? 0.2 * std::sin(7.0 * r + 3.0 * c) : 0.0;
      const double dy = inner ? 0.2 * std::cos(5.0 * r - 2.0 * c) : 0.0;
      V.row(5 * r + c) = (R * qd::common::Vec3(c + dx, r + dy, 0)).transpose();
    }
  }
  F.resize(32, 3);
  int f = 0;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      const int a = 5 * r + c;
      F.row(f++) << a, a + 1, a + 6;
      F.row(f++) << a, a + 6, a + 5;
    }
  }
}

TEST(Metrics, FlatGridHasNoCurvatureInside) {
  qd::common::Positions V;
  qd::common::Triangles F;
  flat_grid(V, F);
  const qd::common::Topology topo = qd::common::analyse_topology(F, 25, {});
  std::vector<char> interior(25, 0);
  int count = 0;
  for (int v = 0; v < 25; ++v) {
    interior[v] = topo.boundary[v] ? 0 : 1;
    count += interior[v];
  }
  ASSERT_EQ(count, 9);
  const std::vector<double> k =
      qd::common::gaussian_curvature(qd::common::vertex_angles(V, F), interior);
  const std::vector<double> defect = qd::common::vertex_angles(V, F).defect;
  for (int v = 0; v < 25; ++v) {
    if (!interior[v]) continue;
    EXPECT_NEAR(defect[v], 0.0, 1e-12) << v;
    EXPECT_NEAR(k[v], 0.0, 1e-11) << v;
  }
  // Mixed areas tile the surface: they add up to the total area (16).
  double total = 0;
  for (const double a : qd::common::vertex_angles(V, F).area) total += a;
  EXPECT_NEAR(total, 16.0, 1e-12);
}

TEST(Metrics, ObdOfTiltedTarget) {
  qd::common::Positions V(3, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  const qd::common::Triangles F = one_face();
  EXPECT_NEAR(qd::common::orientation_developability(V, F, {0}, {qd::common::Vec3(0, 0, 1)}), 0.0,
              1e-15);
  // n = (sin a, 0, cos a): |n·(1,0,0)| + |n·(−1,1,0)| + |n·(0,−1,0)| = 2 sin a.
  const double a = 0.3;
  const qd::common::Vec3 n(std::sin(a), 0, std::cos(a));
  EXPECT_NEAR(qd::common::orientation_developability(V, F, {0}, {n}), 2 * std::sin(a), 1e-15);
  // Summed over faces (Def. 3): the same face twice counts twice.
  qd::common::Triangles F2(2, 3);
  F2 << 0, 1, 2, 0, 1, 2;
  EXPECT_NEAR(qd::common::orientation_developability(V, F2, {0, 1}, {n, n}), 4 * std::sin(a),
              1e-15);
}

TEST(Metrics, ShapeDifferenceOfTranslationAndRotation) {
  qd::common::Positions V0(3, 3);
  V0 << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  const qd::common::Triangles F = one_face();
  // Translation t: edges unchanged (s1 = s2 = 0), s3 = |3t|²/3 = 3|t|².
  const qd::common::Vec3 t(0.1, -0.2, 0.3);
  qd::common::Positions moved = V0.rowwise() + t.transpose();
  EXPECT_NEAR(qd::common::shape_difference(V0, moved, F, {0}), 3 * t.squaredNorm(), 1e-15);
  // 90° about z through v1: v2' = (0,1,0), v3' = (−1,0,0).
  // s1 = |(0,1,0) − (1,0,0)|² = 2, s2 = |(−1,0,0) − (0,1,0)|² = 2,
  // s3 = |(−1,1,0) − (1,1,0)|²/3 = 4/3.
  qd::common::Positions rotated(3, 3);
  rotated << 0, 0, 0, 0, 1, 0, -1, 0, 0;
  EXPECT_NEAR(qd::common::shape_difference(V0, rotated, F, {0}), 2 + 2 + 4.0 / 3, 1e-15);
  EXPECT_EQ(qd::common::shape_difference(V0, V0, F, {0}), 0.0);
}

TEST(Metrics, MeasureCombinesFigures) {
  qd::common::Positions V0;
  qd::common::Triangles F;
  cube_corner(V0, F);
  qd::common::Positions V = V0;
  V.row(1) += qd::common::Vec3(0, 0, 0.3).transpose();
  V.row(2) += qd::common::Vec3(0.4, 0, 0).transpose();
  const std::vector<qd::common::Vec3> targets = {
      qd::common::Vec3(0, 0, 1), qd::common::Vec3(1, 0, 0), qd::common::Vec3(0, 1, 0)};
  const qd::common::Figures fig = qd::common::measure(qd::common::vertex_angles(V, F), V0, V, F,
                                                      {0}, {0, 1, 2}, targets, {1, 2, 3});

  const double k = qd::common::gaussian_curvature(qd::common::vertex_angles(V, F), only(0, 4))[0];
  EXPECT_NEAR(fig.g_abd, std::abs(k), 1e-12);
  EXPECT_NEAR(fig.max_abs_k, std::abs(k), 1e-12);
  EXPECT_NEAR(fig.angle_defect, std::abs(qd::common::vertex_angles(V, F).defect[0]), 1e-12);
  EXPECT_NEAR(fig.obd, qd::common::orientation_developability(V, F, {0, 1, 2}, targets), 1e-12);
  EXPECT_GT(fig.obd, 0.0);
  EXPECT_NEAR(fig.shape, qd::common::shape_difference(V0, V, F, {0, 1, 2}), 1e-12);
  EXPECT_NEAR(fig.max_disp, 0.4, 1e-15);
  EXPECT_NEAR(fig.mean_disp, (0.3 + 0.4 + 0.0) / 3, 1e-15);

  const qd::common::Figures no_targets =
      qd::common::measure(qd::common::vertex_angles(V, F), V0, V, F, {0}, {0, 1, 2}, {}, {1, 2, 3});
  EXPECT_EQ(no_targets.obd, 0.0);
}

TEST(Metrics, MeasureOfUnchangedCubeCorner) {
  qd::common::Positions V;
  qd::common::Triangles F;
  cube_corner(V, F);
  const qd::common::Figures fig = qd::common::measure(qd::common::vertex_angles(V, F), V, V, F, {0},
                                                      {0, 1, 2}, {}, {0, 1, 2, 3});
  EXPECT_NEAR(fig.angle_defect, kPi / 2, 1e-12);
  EXPECT_NEAR(fig.g_abd, 2 * kPi / 3, 1e-12);
  EXPECT_EQ(fig.shape, 0.0);
  EXPECT_EQ(fig.max_disp, 0.0);
  EXPECT_EQ(fig.mean_disp, 0.0);
}

TEST(Metrics, TargetCountMismatchIsAnError) {
  qd::common::Positions V(3, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  EXPECT_THROW(qd::common::orientation_developability(V, one_face(), {0}, {}), std::runtime_error);
}

}  // namespace
