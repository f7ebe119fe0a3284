// The nested marker (nest_marker.h) and the row-by-row one it is compared with (row_marker.h):
// no overlap, inside the strip, the grain along the length, quantities and mirrored copies,
// pieces wider than the fabric reported; and the nesting no longer than the rows.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <polyclipping/clipper.hpp>

#include "nest_marker.h"
#include "row_marker.h"

namespace {

using qd::Marker;
using qd::Outline;
using qd::Pattern;
using qd::PatternPiece;

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
  return qd::make_pattern({piece("1", rectangle(3, 5), 2, 1), piece("2", rectangle(2, 4)),
                           piece("3", rectangle(4, 2), 3)});
}

TEST(NestMarker, PlacesRectanglesWithoutOverlapInsideTheStrip) {
  const Marker m = qd::nest_marker(rectangles(), 8, 0.1);
  ASSERT_EQ(m.placements.size(), 6u);
  EXPECT_TRUE(m.unplaced.empty());
  expect_valid(m);
  EXPECT_GT(m.length, 0);
  // Piece area 2*15 + 8 + 3*8 = 62 on a strip 8 wide: at least 62 / 8 long.
  EXPECT_GE(m.length, 62.0 / 8 - 1e-9);
  EXPECT_NEAR(m.efficiency, 62 / (8 * m.length), 1e-9);
}

TEST(NestMarker, MirrorsTheAskedCopiesAndKeepsTheGrainAlongTheLength) {
  const Marker m = qd::nest_marker(rectangles(), 8, 0.1);
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
      qd::make_pattern({piece("wide", rectangle(12, 3)), piece("ok", rectangle(3, 3))});
  const Marker m = qd::nest_marker(pattern, 8, 0.1);
  ASSERT_EQ(m.unplaced.size(), 1u);
  EXPECT_EQ(m.unplaced[0], "wide");
  ASSERT_EQ(m.placements.size(), 1u);
  expect_valid(m);
  EXPECT_EQ(qd::row_marker(pattern, 8, 0.1).unplaced, m.unplaced);
}

// Triangles and L-shapes, which bounding boxes waste.
Pattern irregular() {
  const Outline triangle = {{0, 0}, {6, 0}, {0, 9}};
  const Outline ell = {{0, 0}, {5, 0}, {5, 2}, {2, 2}, {2, 7}, {0, 7}};
  const Outline slant = {{0, 0}, {4, 0}, {7, 6}, {3, 6}};
  return qd::make_pattern({piece("T", triangle, 4, 2), piece("L", ell, 3), piece("S", slant, 2)});
}

TEST(NestMarker, IsNoLongerThanRowsOnIrregularPieces) {
  const Marker nest = qd::nest_marker(irregular(), 14, 0.1);
  const Marker rows = qd::row_marker(irregular(), 14, 0.1);
  ASSERT_EQ(nest.placements.size(), 9u);
  ASSERT_EQ(rows.placements.size(), 9u);
  expect_valid(nest);
  expect_valid(rows);
  EXPECT_LE(nest.length, rows.length + 1e-9);
  std::cout << "nested: length " << nest.length << ", efficiency " << nest.efficiency
            << "; rows: length " << rows.length << ", efficiency " << rows.efficiency << '\n';
}

}  // namespace
