// Ordering skeleton pixels into a curve (skeleton_curve.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "approximate/skeleton_curve.h"

using qd::approximate::SkeletonPoint;
using qd::approximate::Vec2;

namespace {

using namespace qd::approximate;

constexpr double kPi = 3.14159265358979323846;

SkeletonPoint pixel(int x, int y, double strength = 1.0) {
  return SkeletonPoint{Vec2(x + 0.5, y + 0.5), x, y, strength};
}

}  // namespace

TEST(SkeletonCurve, ChainWithSpurIsOrderedAndSpurDropped) {
  // A chain along y = 10 from x = 0 to 30 (shuffled), with a 5-pixel spur up from x = 15 and
  // a diagonal step in the middle of the chain.
  std::vector<SkeletonPoint> pts;
  for (int x = 0; x <= 30; ++x) pts.push_back(pixel(x, x < 20 ? 10 : 11));
  for (int y = 11; y <= 15; ++y) pts.push_back(pixel(15, y));
  std::reverse(pts.begin() + 5, pts.end() - 10);
  const qd::approximate::OrderedSkeleton c = qd::approximate::order_skeleton(pts, 64, false);
  EXPECT_FALSE(c.closed);
  ASSERT_EQ(c.points.size(), 31u);
  const double dir = c.points.back().x() > c.points.front().x() ? 1 : -1;
  for (size_t k = 1; k < c.points.size(); ++k)
    EXPECT_DOUBLE_EQ(dir * (c.points[k].x() - c.points[k - 1].x()), 1.0);
  for (const Vec2& p : c.points) EXPECT_LT(p.y(), 12.0);  // no spur pixel
}

TEST(SkeletonCurve, SeparateBlobsAreChainedAndWeakOutlierDropped) {
  // Three strong clusters far apart on a line (a coarse mesh's Gauss image) and one faint
  // outlier pixel off the line.
  std::vector<SkeletonPoint> pts = {pixel(40, 5), pixel(41, 5), pixel(5, 5),        pixel(6, 5),
                                    pixel(22, 5), pixel(23, 5), pixel(22, 30, 0.01)};
  const qd::approximate::OrderedSkeleton c = qd::approximate::order_skeleton(pts, 64, false);
  ASSERT_EQ(c.points.size(), 6u);
  const double dir = c.points.back().x() > c.points.front().x() ? 1 : -1;
  for (size_t k = 1; k < c.points.size(); ++k)
    EXPECT_GT(dir * (c.points[k].x() - c.points[k - 1].x()), 0.0);
  for (const Vec2& p : c.points) EXPECT_DOUBLE_EQ(p.y(), 5.5);
}

TEST(SkeletonCurve, PeriodicLoopIsClosedEvenWithSpur) {
  const int W = 50;
  std::vector<SkeletonPoint> pts;
  for (int x = 0; x < W; ++x) pts.push_back(pixel((x + 17) % W, 8 + (x % 10 < 5 ? 0 : 1)));
  for (int y = 9; y <= 20; ++y) pts.push_back(pixel(30, y));  // long spur
  const qd::approximate::OrderedSkeleton c = qd::approximate::order_skeleton(pts, W, true);
  EXPECT_TRUE(c.closed);
  EXPECT_DOUBLE_EQ(std::abs(c.shift.x()), W);
  ASSERT_EQ(c.points.size(), static_cast<size_t>(W));
  for (size_t k = 1; k < c.points.size(); ++k)
    EXPECT_LE((c.points[k] - c.points[k - 1]).norm(), 1.5);
  // The closing step (last -> first + shift) is short too: no cut at the seam.
  EXPECT_LE((c.points.front() + c.shift - c.points.back()).norm(), 1.5);
}

TEST(SkeletonCurve, OpenArcOnPeriodicImageStaysOpen) {
  std::vector<SkeletonPoint> pts;
  for (int x = 45; x < 65; ++x) pts.push_back(pixel(x % 50, 4));  // crosses the seam
  const qd::approximate::OrderedSkeleton c = qd::approximate::order_skeleton(pts, 50, true);
  EXPECT_FALSE(c.closed);
  ASSERT_EQ(c.points.size(), 20u);
  EXPECT_DOUBLE_EQ(std::abs(c.points.back().x() - c.points.front().x()), 19.0);  // unwrapped
}

TEST(SkeletonCurve, ExtendEndsReachesTheSamples) {
  std::vector<Vec2> line;
  for (int x = 10; x <= 40; ++x) line.push_back(Vec2(x, 5));
  std::vector<Vec2> samples;
  for (int k = 0; k <= 400; ++k) samples.push_back(Vec2(4 + 0.1 * k, 5 + 0.5 * std::sin(k)));
  qd::approximate::extend_ends(line, samples, 3.0, 0.0, 2.0);
  const double lo = std::min(line.front().x(), line.back().x());
  const double hi = std::max(line.front().x(), line.back().x());
  EXPECT_NEAR(lo, 4.0, 0.5);
  EXPECT_NEAR(hi, 44.0, 0.5);
  for (const Vec2& p : line) EXPECT_NEAR(p.y(), 5.0, 1e-9);
}

TEST(SkeletonCurve, ExtendEndsFollowsCurvature) {
  // A circular arc of radius 30 (120°); samples continue the circle 20° beyond each end.
  const double R = 30;
  auto at = [&](double deg) {
    return Vec2(R * std::cos(deg * kPi / 180), R * std::sin(deg * kPi / 180));
  };
  std::vector<Vec2> arc, samples;
  for (double a = 30; a <= 150; a += 1.5) arc.push_back(at(a));
  for (double a = 10; a <= 170; a += 0.25) samples.push_back(at(a));
  qd::approximate::extend_ends(arc, samples, 3.0, 0.0, 2.0);
  for (const Vec2& p : arc) EXPECT_NEAR(p.norm(), R, 0.3);
  const double a0 = std::atan2(arc.front().y(), arc.front().x()) * 180 / kPi;
  const double a1 = std::atan2(arc.back().y(), arc.back().x()) * 180 / kPi;
  EXPECT_NEAR(std::min(a0, a1), 10.0, 2.0);
  EXPECT_NEAR(std::max(a0, a1), 170.0, 2.0);
}
