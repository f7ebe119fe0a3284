// The pattern sheet: one piece per group, with its quantity and mirrored count, laid out so
// that no two cut lines' boxes overlap and each piece keeps its shape.
#include <gtest/gtest.h>

#include "flatten/pattern_sheet.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

qd::flatten::PatternPiece rectangle(double w, double h, double x, double y, double allowance) {
  qd::flatten::PatternPiece p;
  p.outlines = {{{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}}};
  p.cut_outlines = {{{x - allowance, y - allowance},
                     {x + w + allowance, y - allowance},
                     {x + w + allowance, y + h + allowance},
                     {x - allowance, y + h + allowance}}};
  p.notches = {{{x + w / 2, y}, {0, 1}, {x + w / 2, y - allowance}}};
  p.label_at = {x + w / 2, y + h / 2};
  return p;
}

Eigen::AlignedBox2d box(const qd::flatten::Outline& o) {
  Eigen::AlignedBox2d b;
  for (const Eigen::Vector2d& p : o) b.extend(p);
  return b;
}

TEST(PatternSheet, KeepsOnePiecePerGroupWithItsQuantityAndMirroredCount) {
  std::vector<qd::flatten::PatternPiece> pieces = {
      rectangle(2, 1, 0, 0, 0.1), rectangle(3, 1, 5, 0, 0.1), rectangle(2, 1, 9, 0, 0.1)};
  pieces[1].label = "1";
  const std::vector<qd::flatten::PieceGroup> groups = {{{0, 2}, {0, 1}, 0.1}, {{1}, {0}, 0}};
  const qd::flatten::Pattern sheet = qd::flatten::pattern_sheet(pieces, groups, 0.5);
  ASSERT_EQ(sheet.pieces.size(), 2u);
  EXPECT_EQ(sheet.pieces[0].quantity, 2);
  EXPECT_EQ(sheet.pieces[0].mirrored, 1);
  EXPECT_EQ(sheet.pieces[1].quantity, 1);
  EXPECT_EQ(sheet.pieces[1].mirrored, 0);
  EXPECT_EQ(sheet.pieces[1].label, "1");
}

TEST(PatternSheet, SeparatesCutLinesByTheGapAndMovesEverythingOfAPieceTogether) {
  std::vector<qd::flatten::PatternPiece> pieces = {rectangle(2, 1, 0, 0, 0.2),
                                                   rectangle(3, 2, 0.5, 0.5, 0.2)};
  const qd::flatten::Pattern sheet =
      qd::flatten::pattern_sheet(pieces, {{{0}, {0}, 0}, {{1}, {0}, 0}}, 0.5);
  Eigen::AlignedBox2d a = box(sheet.pieces[0].cut_outlines[0]),
                      b = box(sheet.pieces[1].cut_outlines[0]);
  const Eigen::AlignedBox2d grown_a(a.min(), a.max() + Eigen::Vector2d(0.49, 0.49));
  EXPECT_FALSE(grown_a.intersects(b) && grown_a.intersection(b).volume() > 0);
  for (const qd::flatten::PatternPiece& p : sheet.pieces) {
    const Eigen::AlignedBox2d sew = box(p.outlines[0]), cut = box(p.cut_outlines[0]);
    EXPECT_NEAR((sew.min() - cut.min()).norm(), 0.2 * std::sqrt(2.0), 1e-12);  // shape kept
    EXPECT_NEAR(p.notches[0].at.y() - p.notches[0].cut_at.y(), 0.2, 1e-12);
    EXPECT_NEAR((p.label_at - sew.center()).norm(), 0, 1e-12);
    EXPECT_TRUE(sheet.bounds.contains(cut));
  }
}

}  // namespace
