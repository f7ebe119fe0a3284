// The cone proxy fit: planes, cylinders and cones are recovered from their normals, a narrow
// band of a cylinder gives its axis, the lower bound never exceeds the fit's largest error, and
// over the limit a far-off face does not tilt the cone for the others.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "segment/cone_fit.h"

namespace qd::test {
namespace {

using namespace qd::common;
using namespace qd::segment;

// Faces of area 1 with normals at `angle` to `axis`, spread over `arc` radians around it.
FaceGeometry cone_normals(const Vec3& axis, double angle, double arc, int count) {
  const Vec3 a = axis.normalized();
  const Vec3 u = a.unitOrthogonal(), v = a.cross(u);
  FaceGeometry g;
  for (int i = 0; i < count; ++i) {
    const double t = arc * (i / double(count - 1) - 0.5);
    g.normal.push_back(std::cos(angle) * a + std::sin(angle) * (std::cos(t) * u + std::sin(t) * v));
    g.area.push_back(1.0);
    g.centroid.push_back(Vec3::Zero());
  }
  return g;
}

std::vector<int> all(const FaceGeometry& g) {
  std::vector<int> faces(g.normal.size());
  std::iota(faces.begin(), faces.end(), 0);
  return faces;
}

const double kLimit = 20 * M_PI / 180;

TEST(ConeFit, PlaneIsAPlaneThroughItsNormal) {
  FaceGeometry g;
  const Vec3 n = Vec3(0.3, -0.5, 0.8).normalized();
  for (int i = 0; i < 10; ++i) {
    g.normal.push_back(n);
    g.area.push_back(1.0 + i);
  }
  const ConeFit fit = fit_cone(g, all(g), kLimit);
  EXPECT_NEAR(fit.proxy.angle, 0.0, 1e-6);
  EXPECT_NEAR(fit.proxy.axis.dot(n), 1.0, 1e-9);
  EXPECT_LT(fit.max_error, 1e-6);
}

TEST(ConeFit, NarrowCylinderStripGivesTheAxis) {
  const Vec3 axis = Vec3(1, 2, 3).normalized();
  const FaceGeometry g = cone_normals(axis, M_PI / 2, 0.3, 20);
  const ConeFit fit = fit_cone(g, all(g), kLimit);
  EXPECT_NEAR(std::abs(fit.proxy.axis.dot(axis)), 1.0, 1e-9);
  EXPECT_NEAR(fit.proxy.angle, M_PI / 2, 1e-9);
  EXPECT_LT(fit.max_error, 1e-9);
}

TEST(ConeFit, ConeGivesAxisAndApexAngle) {
  const Vec3 axis = Vec3(-2, 1, 0.5).normalized();
  const FaceGeometry g = cone_normals(axis, 0.6, 4.0, 40);
  const ConeFit fit = fit_cone(g, all(g), kLimit);
  EXPECT_NEAR(fit.proxy.axis.dot(axis), 1.0, 1e-9);
  EXPECT_NEAR(fit.proxy.angle, 0.6, 1e-9);
  EXPECT_LT(fit.max_error, 1e-9);
  const ConeFit measured = measure_cone(g, all(g), fit.proxy);
  EXPECT_NEAR(measured.max_error, fit.max_error, 1e-12);
}

TEST(ConeFit, ApexAngleIsAtMostNinetyDegrees) {
  const FaceGeometry g = cone_normals(Vec3::UnitZ(), 2.5, 3.0, 30);  // 143° to +z = 37° to −z
  const ConeFit fit = fit_cone(g, all(g), kLimit);
  EXPECT_NEAR(fit.proxy.angle, M_PI - 2.5, 1e-9);
  EXPECT_NEAR(fit.proxy.axis.z(), -1.0, 1e-9);
}

TEST(ConeFit, LowerBoundNeverExceedsTheLargestError) {
  FaceGeometry g = cone_normals(Vec3::UnitX(), 1.0, 2.0, 50);
  for (int i = 0; i < 50; ++i) {  // deterministic wobble of up to ~11°
    g.normal[i] =
        (g.normal[i] + 0.2 * Vec3(std::sin(7.0 * i), std::cos(5.0 * i), std::sin(3.0 * i)))
            .normalized();
    g.area[i] = 1.0 + (i % 3);
  }
  const ConeFit fit = fit_cone(g, all(g), kLimit);
  EXPECT_GT(max_error_lower_bound(normal_moments(g, all(g))), 0.0);
  EXPECT_LE(max_error_lower_bound(normal_moments(g, all(g))), fit.max_error);
}

TEST(ConeFit, OverTheLimitAFarFaceDoesNotTiltTheCone) {
  FaceGeometry g = cone_normals(Vec3::UnitZ(), M_PI / 2, 5.5, 40);  // most of a cylinder
  g.normal.push_back(Vec3::UnitZ());                                // one face far off the cylinder
  g.area.push_back(1.0);
  const ConeFit fit = fit_cone(g, all(g), kLimit);
  EXPECT_GT(fit.max_error, kLimit);
  // The cylinder's faces keep a small error: the cone is the least-squares one, not the one
  // halving the far face's error for everyone.
  std::vector<int> faces(40);
  std::iota(faces.begin(), faces.end(), 0);
  EXPECT_LT(measure_cone(g, faces, fit.proxy).max_error, 0.1);
}

TEST(ConeFit, BetterFitPrefersWithinTheLimitThenSmallestLargestError) {
  ConeFit within, smaller, over_small_rms, over_large_rms;
  within.max_error = 0.3, within.rms_error = 0.2;
  smaller.max_error = 0.1, smaller.rms_error = 0.1;
  over_small_rms.max_error = 1.0, over_small_rms.rms_error = 0.05;
  over_large_rms.max_error = 0.5, over_large_rms.rms_error = 0.3;
  EXPECT_TRUE(better_fit(smaller, within, kLimit));
  EXPECT_TRUE(better_fit(within, over_small_rms, kLimit));
  EXPECT_TRUE(better_fit(over_small_rms, over_large_rms, kLimit));
  ConeFit plane = within, cylinder = within;
  plane.proxy.angle = 0.0;
  cylinder.proxy.angle = M_PI / 2;
  EXPECT_TRUE(better_fit(plane, cylinder, kLimit));
  EXPECT_FALSE(better_fit(cylinder, plane, kLimit));
}

}  // namespace
}  // namespace qd::test
