// The nested marker (nest_marker.h) and the row-by-row one it is compared with (row_marker.h):
// no overlap, inside the strip, the grain along the length, quantities and mirrored copies,
// pieces wider than the fabric reported; the nesting no longer than the rows, and clearly
// shorter where pieces interlock; the exact no-fit polygon it nests with (minkowski_nfp.h).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <polyclipping/clipper.hpp>

#include "cut_marker.h"
#include "minkowski_nfp.h"
#include "nest_marker.h"
#include "row_marker.h"

namespace {

using namespace qd::common;
using namespace qd::marker;

using qd::flatten::Outline;
using qd::flatten::Pattern;
using qd::flatten::PatternPiece;
using qd::marker::Marker;

PatternPiece piece(const std::string& label, Outline outline, int quantity = 1, int mirrored = 0) {
  PatternPiece p;
  p.label = label;
  p.outlines = {outline};
  p.cut_outlines = {std::move(outline)};
  p.quantity = quantity;
  p.mirrored = mirrored;
  return p;
}

Outline rectangle(double w, double h) { return {{0, 0}, {w, 0}, {w, h}, {0, h}}; }

// Overlap area of two outlines, by Clipper in fixed-point units of 1e-6.
double overlap(const Outline& a, const Outline& b) {
  const auto path = [](const Outline& o) {
    ClipperLib::Path p;
    for (const auto& q : o) p.emplace_back(std::llround(q.x() * 1e6), std::llround(q.y() * 1e6));
    return p;
  };
  ClipperLib::Clipper c;
  c.AddPath(path(a), ClipperLib::ptSubject, true);
  c.AddPath(path(b), ClipperLib::ptClip, true);
  ClipperLib::Paths out;
  c.Execute(ClipperLib::ctIntersection, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  double area = 0;
  for (const auto& p : out) area += std::abs(ClipperLib::Area(p));
  return area * 1e-12;
}

// The properties every marker has: no two pieces overlap, all inside [0, length] x [0, width],
// an efficiency in (0, 1].
void expect_valid(const Marker& m) {
  const double eps = 1e-6 * m.width;
  for (size_t i = 0; i < m.placements.size(); ++i) {
    for (const auto& q : m.placements[i].outline) {
      EXPECT_GE(q.x(), -eps);
      EXPECT_LE(q.x(), m.length + eps);
      EXPECT_GE(q.y(), -eps);
      EXPECT_LE(q.y(), m.width + eps);
    }
    for (size_t j = 0; j < i; ++j)
      EXPECT_NEAR(overlap(m.placements[i].outline, m.placements[j].outline), 0,
                  1e-6 * m.width * m.width)
          << "pieces " << i << " and " << j;
  }
  EXPECT_GT(m.efficiency, 0);
  EXPECT_LE(m.efficiency, 1 + 1e-9);
}

Pattern rectangles() {
  return qd::flatten::make_pattern({piece("1", rectangle(3, 5), 2, 1), piece("2", rectangle(2, 4)),
                                    piece("3", rectangle(4, 2), 3)});
}

TEST(NestMarker, PlacesRectanglesWithoutOverlapInsideTheStrip) {
  const Marker m = qd::marker::nest_marker(rectangles(), 8, 0.1);
  ASSERT_EQ(m.placements.size(), 6u);
  EXPECT_TRUE(m.unplaced.empty());
  expect_valid(m);
  EXPECT_GT(m.length, 0);
  // Piece area 2*15 + 8 + 3*8 = 62 on a strip 8 wide: at least 62 / 8 long.
  EXPECT_GE(m.length, 62.0 / 8 - 1e-9);
  EXPECT_NEAR(m.efficiency, 62 / (8 * m.length), 1e-9);
}

TEST(NestMarker, MirrorsTheAskedCopiesAndKeepsTheGrainAlongTheLength) {
  const Marker m = qd::marker::nest_marker(rectangles(), 8, 0.1);
  int mirrored = 0;
  for (const auto& p : m.placements) {
    if (p.piece == 0 && p.mirrored) ++mirrored;
    EXPECT_TRUE(!p.mirrored || p.piece == 0);
    // Grain +y on the sheet onto +-x: a quarter turn either way.
    EXPECT_NEAR(std::abs(std::sin(p.rotation)), 1, 1e-9);
    const Eigen::Vector2d grain = Eigen::Rotation2Dd(p.rotation) * Eigen::Vector2d::UnitY();
    EXPECT_NEAR(std::abs(grain.x()), 1, 1e-9);
  }
  EXPECT_EQ(mirrored, 1);
}

TEST(NestMarker, ReportsAPieceWiderThanTheFabric) {
  // On the marker a piece's sheet x runs across the width: 12 > 8.
  const Pattern pattern =
      qd::flatten::make_pattern({piece("wide", rectangle(12, 3)), piece("ok", rectangle(3, 3))});
  const Marker m = qd::marker::nest_marker(pattern, 8, 0.1);
  ASSERT_EQ(m.unplaced.size(), 1u);
  EXPECT_EQ(m.unplaced[0], "wide");
  ASSERT_EQ(m.placements.size(), 1u);
  expect_valid(m);
  EXPECT_EQ(qd::marker::row_marker(pattern, 8, 0.1).unplaced, m.unplaced);
}

// Triangles and L-shapes, which bounding boxes waste.
Pattern irregular() {
  const Outline triangle = {{0, 0}, {6, 0}, {0, 9}};
  const Outline ell = {{0, 0}, {5, 0}, {5, 2}, {2, 2}, {2, 7}, {0, 7}};
  const Outline slant = {{0, 0}, {4, 0}, {7, 6}, {3, 6}};
  return qd::flatten::make_pattern(
      {piece("T", triangle, 4, 2), piece("L", ell, 3), piece("S", slant, 2)});
}

TEST(NestMarker, IsNoLongerThanRowsOnIrregularPieces) {
  const Marker nest = qd::marker::nest_marker(irregular(), 14, 0.1);
  const Marker rows = qd::marker::row_marker(irregular(), 14, 0.1);
  ASSERT_EQ(nest.placements.size(), 9u);
  ASSERT_EQ(rows.placements.size(), 9u);
  expect_valid(nest);
  expect_valid(rows);
  EXPECT_LE(nest.length, rows.length + 1e-9);
  std::cout << "nested: length " << nest.length << ", efficiency " << nest.efficiency
            << "; rows: length " << rows.length << ", efficiency " << rows.efficiency << '\n';
}

// An L tromino: two of them, one turned half round, make a 3 x 2 rectangle.
Outline tromino(double s) {
  return {{0, 0}, {2 * s, 0}, {2 * s, s}, {s, s}, {s, 2 * s}, {0, 2 * s}};
}

TEST(NestMarker, InterlocksTwoLShapesIntoTheirRectangle) {
  const double s = 5, gap = 0.01;
  const Pattern pattern = qd::flatten::make_pattern({piece("L", tromino(s), 2)});
  const Marker m = qd::marker::nest_marker(pattern, 2 * s + 1, gap);
  ASSERT_EQ(m.placements.size(), 2u);
  expect_valid(m);
  // Side by side their bounding boxes need 4 s; interlocked they touch along the notch: 3 s.
  EXPECT_LT(m.length, 3.5 * s);
}

TEST(NestMarker, IsClearlyShorterThanRowsWhereLShapesInterlock) {
  const double s = 5, gap = 0.1;
  const Pattern pattern = qd::flatten::make_pattern({piece("L", tromino(s), 8, 4)});
  // Two boxes across: the rows stack them, the nesting has to interlock pairs to do better.
  const Marker nest = qd::marker::nest_marker(pattern, 4 * s + 1, gap);
  const Marker rows = qd::marker::row_marker(pattern, 4 * s + 1, gap);
  ASSERT_EQ(nest.placements.size(), 8u);
  expect_valid(nest);
  // Pairs in 3 x 2 rectangles against 2 x 2 boxes: a quarter shorter at best.
  EXPECT_LE(nest.length, 0.9 * rows.length);
  std::cout << "L shapes nested: length " << nest.length << "; rows: length " << rows.length
            << '\n';
}

// Clipper's integer polygon of an outline scaled by 1000.
ClipperLib::Path integer_path(const Outline& o) {
  ClipperLib::Path p;
  for (const auto& q : o) p.emplace_back(std::llround(q.x() * 1e3), std::llround(q.y() * 1e3));
  return p;
}

TEST(NoFitPolygon, OfTwoUnitSquaresIsTheTwoByTwoSquareAround) {
  const ClipperLib::Path square = integer_path(rectangle(1, 1));
  const ClipperLib::Path nfp = qd::marker::no_fit_polygon(square, square, {0, 0});
  EXPECT_NEAR(ClipperLib::Area(nfp), 4e6, 1);
  for (const auto& q : nfp) {
    EXPECT_TRUE(std::abs(q.X) == 1000 || std::abs(q.Y) == 1000) << q.X << ' ' << q.Y;
    EXPECT_LE(std::max(std::abs(q.X), std::abs(q.Y)), 1000);
  }
}

// A 3 x 3 U, its notch 1 wide and 2 deep, open at the top.
Outline u_shape() { return {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}; }

TEST(NoFitPolygon, LetsASmallSquareIntoAUsNotch) {
  // A square of side 0.8 moved by its bottom left corner.
  const ClipperLib::Path nfp = qd::marker::no_fit_polygon(
      integer_path(u_shape()), integer_path(rectangle(0.8, 0.8)), {0, 0});
  const auto where = [&nfp](double x, double y) {
    return ClipperLib::PointInPolygon({std::llround(x * 1e3), std::llround(y * 1e3)}, nfp);
  };
  EXPECT_EQ(where(1.1, 1.5), 0);   // in the notch, clear of the U: outside the polygon
  EXPECT_EQ(where(1.1, 1), -1);    // on the notch's floor: on it
  EXPECT_EQ(where(0.5, 0.5), 1);   // on the U: inside
  EXPECT_EQ(where(-0.5, 1.5), 1);  // over the left arm
  EXPECT_EQ(where(-1, 1.5), 0);    // left of it
}

TEST(NestMarker, PutsASmallSquareIntoAUsNotch) {
  const Pattern pattern =
      qd::flatten::make_pattern({piece("U", u_shape()), piece("square", rectangle(0.8, 0.8))});
  const Marker m = qd::marker::nest_marker(pattern, 3.2, 0.05);
  ASSERT_EQ(m.placements.size(), 2u);
  expect_valid(m);
  Eigen::AlignedBox2d u_box, square_box;
  for (const auto& p : m.placements)
    for (const auto& q : p.outline) (p.piece == 0 ? u_box : square_box).extend(q);
  EXPECT_TRUE(u_box.contains(square_box));
}

// The marker written keeps the placement with more pieces placed, then the shorter one.
TEST(CutMarker, KeepsTheShorterOfNestingAndRows) {
  for (const double width : {7.5, 12.0, 15.0, 20.0}) {
    const qd::marker::MarkerChoice c = qd::marker::cut_marker(irregular(), width, 0.1);
    const size_t nested = c.nested.placements.size(), rows = c.rows.placements.size();
    if (nested == rows)
      EXPECT_EQ(c.kept().length, std::min(c.nested.length, c.rows.length)) << width;
    else
      EXPECT_EQ(c.kept().placements.size(), std::max(nested, rows)) << width;
    expect_valid(c.kept());
  }
}

}  // namespace
