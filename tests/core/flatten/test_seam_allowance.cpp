// Seam allowance: the cut line lies the allowance outside the sew line, sharp corners are
// squared off at the miter limit, holes shrink, notches are cut through to the cut line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "flatten/seam_allowance.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

using qd::flatten::Outline;

double signed_area(const Outline& loop) {
  double sum = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector2d& a = loop[i];
    const Eigen::Vector2d& b = loop[(i + 1) % loop.size()];
    sum += a.x() * b.y() - a.y() * b.x();
  }
  return sum / 2;
}

// Distance from p to the nearest edge of the loops.
double distance(const Eigen::Vector2d& p, const std::vector<Outline>& loops) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const Outline& loop : loops)
    for (size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector2d a = loop[i], ab = loop[(i + 1) % loop.size()] - a;
      const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (a + t * ab - p).norm());
    }
  return nearest;
}

Outline square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

Outline reversed(Outline loop) {
  std::reverse(loop.begin(), loop.end());
  return loop;
}

TEST(SeamAllowance, SquareGrowsByTheAllowanceOnEverySide) {
  const double s = 2, a = 0.1, eps = 1e-6;
  for (const Outline& sew : {square(3, -1, s), reversed(square(3, -1, s))}) {
    const std::vector<Outline> cut = qd::flatten::cut_lines({sew}, a);
    ASSERT_EQ(cut.size(), 1u);
    EXPECT_NEAR(signed_area(cut[0]), (s + 2 * a) * (s + 2 * a), 1e-6);  // counter-clockwise
    for (const Eigen::Vector2d& p : cut[0]) {
      EXPECT_GE(distance(p, {sew}), a - eps);
      EXPECT_LE(distance(p, {sew}), a * std::sqrt(2.0) + eps);  // a square corner keeps its miter
    }
  }
}

TEST(SeamAllowance, SharpCornerIsSquaredOffAtTheMiterLimit) {
  const Outline sliver = {{0, 0}, {10, 0}, {0, 1}};  // about 5.7° at (10, 0)
  const double a = 0.2, eps = 1e-6;
  const std::vector<Outline> cut = qd::flatten::cut_lines({sliver}, a);
  ASSERT_EQ(cut.size(), 1u);
  double farthest = 0;
  for (const Eigen::Vector2d& p : cut[0]) {
    EXPECT_GE(distance(p, {sliver}), a - eps);
    farthest = std::max(farthest, distance(p, {sliver}));
  }
  EXPECT_LE(farthest, 2 * a + eps);  // a full miter would reach a / sin(2.86°) ≈ 20 a
}

TEST(SeamAllowance, HoleShrinksWhicheverWayThePieceTurns) {
  const double a = 0.1;
  const std::vector<Outline> ccw = {square(0, 0, 4), reversed(square(1, 1, 2))};
  const std::vector<Outline> cw = {reversed(ccw[0]), reversed(ccw[1])};  // a mirrored piece
  for (const std::vector<Outline>& sew : {ccw, cw}) {
    const std::vector<Outline> cut = qd::flatten::cut_lines(sew, a);
    ASSERT_EQ(cut.size(), 2u);
    std::vector<double> areas = {signed_area(cut[0]), signed_area(cut[1])};
    std::sort(areas.begin(), areas.end());
    EXPECT_NEAR(areas[0], -(2 - 2 * a) * (2 - 2 * a), 1e-6);  // the hole, clockwise
    EXPECT_NEAR(areas[1], (4 + 2 * a) * (4 + 2 * a), 1e-6);
  }
}

TEST(SeamAllowance, ZeroAllowanceKeepsTheSewLines) {
  const std::vector<Outline> sew = {reversed(square(0.3, 0.7, 1.9)), square(0.5, 0.9, 0.2)};
  const std::vector<Outline> cut = qd::flatten::cut_lines(sew, 0);
  ASSERT_EQ(cut.size(), sew.size());
  for (size_t k = 0; k < sew.size(); ++k) EXPECT_EQ(cut[k], sew[k]);
}

TEST(SeamAllowance, NotchesAreCutThroughToTheCutLine) {
  qd::flatten::PatternPiece piece;
  piece.outlines = {square(0, 0, 2)};
  piece.notches = {{{1, 0}, {0, 1}, {1, 0}},
                   {{2, 2}, Eigen::Vector2d(-1, -1).normalized(), {2, 2}}};
  const double a = 0.1;
  qd::flatten::add_seam_allowance(piece, a);
  EXPECT_NEAR((piece.notches[0].cut_at - Eigen::Vector2d(1, -a)).norm(), 0, 1e-6);
  EXPECT_NEAR((piece.notches[1].cut_at - Eigen::Vector2d(2 + a, 2 + a)).norm(), 0,
              1e-6);  // the miter's tip
  for (const qd::flatten::Notch& n : piece.notches)
    EXPECT_NEAR(distance(n.cut_at, piece.cut_outlines), 0, 1e-9);
  qd::flatten::add_seam_allowance(piece, 0);
  EXPECT_EQ(piece.cut_outlines, piece.outlines);
  for (const qd::flatten::Notch& n : piece.notches) EXPECT_EQ(n.cut_at, n.at);
}

}  // namespace
