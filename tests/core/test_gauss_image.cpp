// DEGI moments, shape tests and the rotation R of Eq. 9 (gauss_image.h).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "approximate/gauss_image.h"
#include "common/error.h"
#include "test_gauss_samples.h"

using namespace qd_test;

TEST(GaussImage, ThetaPhiRoundTripAndRange) {
  for (double theta : {0.0, 0.5, 3.0, 4.0, 6.2})
    for (double phi : {0.1, 1.0, 1.5707963, 2.9}) {
      const Vec3 m = qd::approximate::sphere_point(theta, phi);
      EXPECT_NEAR(m.norm(), 1.0, 1e-15);
      const qd::approximate::Vec2 tp = qd::approximate::theta_phi(m);
      EXPECT_NEAR(tp.x(), theta, 1e-12);
      EXPECT_NEAR(tp.y(), phi, 1e-12);
    }
  EXPECT_GE(qd::approximate::theta_phi(Vec3(1, -1e-9, 0).normalized()).x(), 0.0);  // θ ∈ [0, 2π)
}

TEST(GaussImage, MomentsRejectBadInput) {
  const std::vector<Vec3> n = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  EXPECT_NO_THROW(qd::approximate::gauss_moments(n, {1, 1, 1}));
  EXPECT_THROW(qd::approximate::gauss_moments(n, {1, 1, 0}), qd::common::Error);
  EXPECT_THROW(qd::approximate::gauss_moments(n, {1, 1}), qd::common::Error);
  EXPECT_THROW(qd::approximate::gauss_moments(n, {1, 1, std::nan("")}), qd::common::Error);
  EXPECT_THROW(
      qd::approximate::gauss_moments({Vec3::UnitX(), Vec3::UnitY(), Vec3(0, 0, 2)}, {1, 1, 1}),
      qd::common::Error);
  const qd::approximate::GaussMoments m = qd::approximate::gauss_moments(n, {1, 2, 0.5});
  EXPECT_DOUBLE_EQ(m.total_area, 3.5);
  EXPECT_TRUE(m.resultant.isApprox(Vec3(1, 2, 0.5)));
}

TEST(GaussImage, FillsSphereOnlyForSphereLikeImages) {
  const Samples sphere = curve_samples(
      Eigen::Matrix3d::Identity(), 0, 0, [](double) { return 0.0; }, 0, 0, 3000);
  EXPECT_TRUE(
      qd::approximate::fills_sphere(qd::approximate::gauss_moments(sphere.normals, sphere.areas)));
  Samples hemisphere = sphere;
  for (Vec3& v : hemisphere.normals) v.z() = std::abs(v.z());
  EXPECT_FALSE(qd::approximate::fills_sphere(
      qd::approximate::gauss_moments(hemisphere.normals, hemisphere.areas)));
  const Samples tube = cylinder(Vec3(1, 1, 0), 0, 2 * kPi, 2000, 2 * kDeg);
  EXPECT_FALSE(
      qd::approximate::fills_sphere(qd::approximate::gauss_moments(tube.normals, tube.areas)));
}

TEST(GaussImage, PointLikeDetectsPlanesNotShortArcs) {
  const Vec3 n0 = Vec3(1, -2, 0.5).normalized();
  auto flat = [](double) { return 0.0; };
  const Samples plane = curve_samples(frame_for(n0), 0, 0, flat, 500, 0.4 * kDeg);
  EXPECT_TRUE(qd::approximate::is_point_like(
      plane.normals, plane.areas, qd::approximate::gauss_moments(plane.normals, plane.areas)));
  const Samples blob = curve_samples(frame_for(n0), 0, 0, flat, 500, 3 * kDeg);  // noisy plane
  EXPECT_TRUE(qd::approximate::is_point_like(
      blob.normals, blob.areas, qd::approximate::gauss_moments(blob.normals, blob.areas)));
  const Samples arc = cylinder(Vec3(0, 0, 1), 0, 12 * kDeg, 500, 0.3 * kDeg);
  EXPECT_FALSE(qd::approximate::is_point_like(
      arc.normals, arc.areas, qd::approximate::gauss_moments(arc.normals, arc.areas)));
}

TEST(GaussImage, GreatCirclePoleIsTheCylinderAxisDespiteOutliers) {
  const Vec3 axis = Vec3(0.2, 0.7, -0.4).normalized();
  Samples s = cylinder(axis, 0, 120 * kDeg, 2000, 1 * kDeg);
  // 5% of the area in a cluster 40° off the circle (e.g. a folded flap).
  const Eigen::Matrix3d F = frame_for(axis);
  for (int k = 0; k < 100; ++k) {
    s.normals.push_back(F * qd::approximate::sphere_point(60 * kDeg, 50 * kDeg));
    s.areas.push_back(1.0);
  }
  const qd::approximate::GaussMoments m = qd::approximate::gauss_moments(s.normals, s.areas);
  const Vec3 p = qd::approximate::best_great_circle_pole(s.normals, s.areas, m);
  EXPECT_NEAR(p.norm(), 1.0, 1e-12);
  const double refined = std::min(angle(p, axis), angle(-p, axis)) / kDeg;
  EXPECT_LT(refined, 0.5);
  // The least-squares start alone is pulled further by the cluster.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(m.scatter);
  const Vec3 p0 = es.eigenvectors().col(0);
  EXPECT_GT(std::min(angle(p0, axis), angle(-p0, axis)) / kDeg, 2 * refined);
}

TEST(GaussImage, PoleSignComesFromTheData) {
  // The pole leans towards the normals (Σ a n·p >= 0): flipping the normals flips it.
  for (const Vec3& axis : {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 1, 1).normalized()}) {
    Samples s = cone(axis, 70 * kDeg, 0, 150 * kDeg, 1000, 0.5 * kDeg);
    const Vec3 p = qd::approximate::best_great_circle_pole(
        s.normals, s.areas, qd::approximate::gauss_moments(s.normals, s.areas));
    double lean = 0;
    for (size_t i = 0; i < s.normals.size(); ++i) lean += s.areas[i] * s.normals[i].dot(p);
    EXPECT_GT(lean, 0.0);
    for (Vec3& n : s.normals) n = -n;
    const Vec3 q = qd::approximate::best_great_circle_pole(
        s.normals, s.areas, qd::approximate::gauss_moments(s.normals, s.areas));
    EXPECT_LT((p + q).norm(), 1e-9);
  }
}

TEST(GaussImage, FrameCentresTheWidestGapOnTheSeam) {
  const Vec3 axis = Vec3(0.3, 0.3, 0.9).normalized();
  const Samples s = cylinder(axis, 1.0, 1.0 + 200 * kDeg, 1000, 0.2 * kDeg, 5);  // 5 stray outliers
  const qd::approximate::GaussMoments m = qd::approximate::gauss_moments(s.normals, s.areas);
  const qd::approximate::GaussFrame f = qd::approximate::gauss_frame(
      s.normals, s.areas, qd::approximate::best_great_circle_pole(s.normals, s.areas, m));
  EXPECT_FALSE(f.closed);
  // The gap may swallow up to 1% of the area (stray outliers, thin ends): 2° of this arc.
  EXPECT_GT(f.gap / kDeg, 160.0 - 0.5);
  EXPECT_LT(f.gap / kDeg, 162.0 + 0.5);
  EXPECT_TRUE((f.R * f.R.transpose()).isIdentity(1e-12));
  EXPECT_NEAR(f.R.determinant(), 1.0, 1e-12);
  // Centred on the seam: the gap is bounded by two samples at θ = gap/2 and 2π − gap/2, and
  // holds at most 1% of the area (here 10 arc samples plus the outliers).
  int inside_gap = 0;
  double to_lo = 1e9, to_hi = 1e9;
  for (size_t i = 0; i < 1000; ++i) {
    const double theta = qd::approximate::theta_phi(f.R * s.normals[i]).x();
    inside_gap += theta < 0.5 * f.gap - 1e-9 || theta > 2 * kPi - 0.5 * f.gap + 1e-9;
    to_lo = std::min(to_lo, std::abs(theta - 0.5 * f.gap));
    to_hi = std::min(to_hi, std::abs(theta - (2 * kPi - 0.5 * f.gap)));
  }
  EXPECT_LE(inside_gap, 12);
  EXPECT_LT(to_lo, 1e-9);
  EXPECT_LT(to_hi, 1e-9);
}

TEST(GaussImage, FrameDetectsTubes) {
  const Samples tube = cylinder(Vec3(1, 0, 0), 0, 2 * kPi, 2000, 0.5 * kDeg);
  const Samples arc = cylinder(Vec3(1, 0, 0), 0, 300 * kDeg, 2000, 0.5 * kDeg);
  for (const Samples* s : {&tube, &arc}) {
    const qd::approximate::GaussMoments m = qd::approximate::gauss_moments(s->normals, s->areas);
    const qd::approximate::GaussFrame f = qd::approximate::gauss_frame(
        s->normals, s->areas, qd::approximate::best_great_circle_pole(s->normals, s->areas, m));
    EXPECT_EQ(f.closed, s == &tube);
  }
}
