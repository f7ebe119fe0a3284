// Least-squares cubic B-splines (bspline.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "approximate/bspline.h"
#include "common/error.h"

using qd::approximate::Vec2;

namespace {

using namespace qd::approximate;
using namespace qd::common;

constexpr double kPi = 3.14159265358979323846;

Vec2 cubic(double t) { return Vec2(t * t * t - 2 * t + 1, 2 * t * t + 0.5 * t * t * t); }
Vec2 cubic_d1(double t) { return Vec2(3 * t * t - 2, 4 * t + 1.5 * t * t); }
Vec2 cubic_d2(double t) { return Vec2(6 * t, 4 + 3 * t); }

}  // namespace

TEST(BSpline, OpenFitReproducesCubicPolynomialExactly) {
  std::vector<Vec2> pts;
  std::vector<double> u;
  for (int j = 0; j <= 40; ++j) {
    u.push_back(j / 40.0);
    pts.push_back(cubic(u.back()));
  }
  const qd::approximate::BSpline2 s = qd::approximate::fit_bspline(pts, u, 7, 0.0, false);
  for (double t : {0.0, 0.013, 0.37, 0.5, 0.77, 0.999, 1.0}) {
    const qd::approximate::CurvePoint p = s.eval(t);
    EXPECT_LT((p.c - cubic(t)).norm(), 1e-10) << t;
    EXPECT_LT((p.d1 - cubic_d1(t)).norm(), 1e-8) << t;
    EXPECT_LT((p.d2 - cubic_d2(t)).norm(), 1e-6) << t;
  }
}

TEST(BSpline, ClampedEndsInterpolateEndControlPoints) {
  const std::vector<Vec2> ctrl = {Vec2(0, 0), Vec2(1, 2), Vec2(2, -1), Vec2(3, 3), Vec2(4, 0)};
  const qd::approximate::BSpline2 s(ctrl, false);
  EXPECT_LT((s.eval(0.0).c - ctrl.front()).norm(), 1e-14);
  EXPECT_LT((s.eval(1.0).c - ctrl.back()).norm(), 1e-14);
  // Derivatives agree with finite differences.
  for (double t : {0.1, 0.45, 0.8}) {
    const double h = 1e-6;
    const Vec2 fd = (s.eval(t + h).c - s.eval(t - h).c) / (2 * h);
    EXPECT_LT((s.eval(t).d1 - fd).norm(), 1e-6);
    const Vec2 fd2 = (s.eval(t + h).d1 - s.eval(t - h).d1) / (2 * h);
    EXPECT_LT((s.eval(t).d2 - fd2).norm(), 1e-5);
  }
}

TEST(BSpline, PeriodicFitClosesAndFollowsACircle) {
  std::vector<Vec2> pts;
  for (int j = 0; j < 60; ++j)
    pts.push_back(Vec2(std::cos(2 * kPi * j / 60), std::sin(2 * kPi * j / 60)));
  const std::vector<double> u = qd::approximate::chord_length_params(pts, true);
  const qd::approximate::BSpline2 s = qd::approximate::fit_bspline(pts, u, 12, 0.0, true);
  // Closes with continuous tangent and curvature.
  EXPECT_LT((s.eval(1.0 - 1e-12).c - s.eval(0.0).c).norm(), 1e-9);
  EXPECT_LT((s.eval(1.0 - 1e-12).d1 - s.eval(0.0).d1).norm(), 1e-7);
  EXPECT_LT((s.eval(1.0 - 1e-12).d2 - s.eval(0.0).d2).norm(), 1e-5);
  for (int k = 0; k < 200; ++k) EXPECT_NEAR(s.eval(k / 200.0).c.norm(), 1.0, 2e-3);
}

TEST(BSpline, PeriodShiftWindsAroundTheDomain) {
  // θ advances by 2π per period, φ oscillates: a curve around a tube.
  const Vec2 shift(2 * kPi, 0);
  std::vector<Vec2> pts;
  for (int j = 0; j < 80; ++j) {
    const double t = 2 * kPi * j / 80;
    pts.push_back(Vec2(t, 0.3 * std::sin(t)));
  }
  const std::vector<double> u = qd::approximate::chord_length_params(pts, true, shift);
  const qd::approximate::BSpline2 s = qd::approximate::fit_bspline(pts, u, 16, 0.0, true, shift);
  EXPECT_LT((s.eval(1.0).c - (s.eval(0.0).c + shift)).norm(), 1e-9);
  for (size_t j = 0; j < pts.size(); ++j) EXPECT_LT((s.eval(u[j]).c - pts[j]).norm(), 2e-3);
}

TEST(BSpline, ChordLengthParameters) {
  const std::vector<Vec2> pts = {Vec2(0, 0), Vec2(3, 0), Vec2(3, 4)};
  const std::vector<double> open = qd::approximate::chord_length_params(pts, false);
  EXPECT_DOUBLE_EQ(open[1], 3.0 / 7.0);
  EXPECT_DOUBLE_EQ(open[2], 1.0);
  const std::vector<double> closed = qd::approximate::chord_length_params(pts, true);
  EXPECT_DOUBLE_EQ(closed[1], 3.0 / 12.0);
  EXPECT_DOUBLE_EQ(closed[2], 7.0 / 12.0);
  EXPECT_THROW(qd::approximate::chord_length_params({Vec2(1, 1), Vec2(1, 1)}, false),
               qd::common::Error);
}

TEST(BSpline, SmoothingPenaltyCalmsNoisyControlPolygon) {
  std::mt19937 rng(1);
  std::normal_distribution<double> g(0.0, 0.05);
  std::vector<Vec2> pts;
  std::vector<double> u;
  for (int j = 0; j <= 100; ++j) {
    u.push_back(j / 100.0);
    pts.push_back(Vec2(u.back(), g(rng)));
  }
  auto roughness = [](const qd::approximate::BSpline2& s) {
    double r = 0;
    for (int i = 1; i + 1 < s.control_count(); ++i)
      r += (s.control()[i - 1] - 2 * s.control()[i] + s.control()[i + 1]).squaredNorm();
    return r;
  };
  const double rough0 = roughness(qd::approximate::fit_bspline(pts, u, 30, 0.0, false));
  const double rough1 = roughness(qd::approximate::fit_bspline(pts, u, 30, 1.0, false));
  EXPECT_LT(rough1, 0.5 * rough0);
}

TEST(BSpline, SingularFitThrows) {
  // All data at one parameter, no smoothing: the control points are undetermined.
  const std::vector<Vec2> pts(10, Vec2(1, 2));
  const std::vector<double> u(10, 0.5);
  EXPECT_THROW(qd::approximate::fit_bspline(pts, u, 8, 0.0, false), qd::common::Error);
  EXPECT_NO_THROW(qd::approximate::fit_bspline(pts, u, 8, 0.1, true));
}
