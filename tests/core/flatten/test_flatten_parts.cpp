// The flattening's small parts: boundary curve, per-face stretch, boundary crossings, layout.
#include <gtest/gtest.h>

#include <cmath>

#include "flatten/boundary_crossings.h"
#include "flatten/boundary_curve.h"
#include "flatten/face_distortion.h"
#include "flatten/layout.h"

namespace {

using namespace qd::flatten;

TEST(BoundaryCurve, SquareFromItsTurnsAndLengths) {
  const Eigen::Vector4d lengths(2, 1, 2, 1), turning = Eigen::Vector4d::Constant(M_PI / 2);
  const Eigen::MatrixX2d c = qd::flatten::closed_boundary_curve(lengths, turning);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR((c.row((i + 1) % 4) - c.row(i)).norm(), lengths(i), 1e-12);
}

TEST(BoundaryCurve, LengthsThatDoNotCloseAreAdjustedLeastAndClose) {
  const Eigen::Vector4d lengths(2, 1, 1.8, 1), turning = Eigen::Vector4d::Constant(M_PI / 2);
  const Eigen::MatrixX2d c = qd::flatten::closed_boundary_curve(lengths, turning);
  Eigen::Vector4d closed;
  for (int i = 0; i < 4; ++i) closed(i) = (c.row((i + 1) % 4) - c.row(i)).norm();
  // The gap of 0.2 is shared by the two long edges in proportion to their lengths (N = 1/l).
  EXPECT_NEAR(closed(0), 2 - 0.2 * 2 / 3.8, 1e-12);
  EXPECT_NEAR(closed(2), 1.8 + 0.2 * 1.8 / 3.8, 1e-12);
  EXPECT_NEAR(closed(1), 1, 1e-12);
  EXPECT_NEAR(closed(0), closed(2), 1e-12);
}

TEST(FaceDistortion, SingularValuesOfAScaledRotation) {
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(0.7).toRotationMatrix();
  const qd::flatten::Stretch s =
      qd::flatten::stretch(R * Eigen::Vector2d(2.0, 0.5).asDiagonal() * R.transpose() * R);
  EXPECT_NEAR(s.s1, 2.0, 1e-12);
  EXPECT_NEAR(s.s2, 0.5, 1e-12);
  EXPECT_FALSE(s.flipped);
  EXPECT_NEAR(qd::flatten::length_distortion(s), 1.0, 1e-12);
  EXPECT_TRUE(qd::flatten::stretch(Eigen::Vector2d(1.0, -1.0).asDiagonal()).flipped);
}

TEST(FaceDistortion, SignedStretchReadsCompressionNegative) {
  EXPECT_NEAR(qd::flatten::signed_stretch({1.1, 0.95, false}), 0.1, 1e-15);
  EXPECT_NEAR(qd::flatten::signed_stretch({1.02, 0.9, false}), -0.1, 1e-15);
  EXPECT_NEAR(qd::flatten::signed_stretch({0.99, 0.98, false}), -0.02, 1e-15);
  EXPECT_NEAR(qd::flatten::signed_stretch({1.0, 1.0, false}), 0.0, 1e-15);
}

TEST(BoundaryCrossings, FigureEightCrossesASquareDoesNot) {
  Eigen::MatrixX2d uv(4, 2);
  uv << 0, 0, 1, 0, 1, 1, 0, 1;
  const std::vector<std::array<int, 2>> square = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  EXPECT_EQ(qd::flatten::crossing_segments(uv, square), std::vector<char>(4, 0));
  const std::vector<std::array<int, 2>> bow = {{0, 1}, {1, 3}, {3, 2}, {2, 0}};  // 1→3 crosses 2→0
  EXPECT_EQ(qd::flatten::crossing_segments(uv, bow), (std::vector<char>{0, 1, 0, 1}));
}

TEST(Layout, GrainEndsUpAlongY) {
  for (const double angle : {0.0, 0.4, 2.0, -2.9}) {
    const Eigen::Vector2d grain(std::cos(angle), std::sin(angle));
    const Eigen::Matrix2d R = qd::flatten::grain_rotation(grain);
    EXPECT_NEAR((R * grain - Eigen::Vector2d::UnitY()).norm(), 0.0, 1e-12) << angle;
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12) << angle;  // turned, not mirrored
    EXPECT_NEAR((R.transpose() * R - Eigen::Matrix2d::Identity()).norm(), 0.0, 1e-12) << angle;
  }
}

TEST(Layout, LaysEachPieceWithItsGrainUp) {
  Eigen::MatrixX2d thin(4, 2);
  thin << 0, 0, 3, 3, 0.5, -0.5, 3.5, 2.5;  // a long thin parallelogram along (1, 1)
  std::vector<Eigen::MatrixX2d> pieces = {thin, thin};
  const std::vector<Eigen::Vector2d> grain = {Eigen::Vector2d(1, 1).normalized(),
                                              Eigen::Vector2d(1, -1).normalized()};
  const double gap = 0.2, margin = 0.3;
  const std::vector<Eigen::AlignedBox2d> boxes = qd::flatten::lay_out(pieces, grain, gap, margin);
  // Grown by the margin, the boxes keep the gap apart.
  Eigen::AlignedBox2d grown[2];
  for (int k = 0; k < 2; ++k)
    grown[k] = {boxes[k].min().array() - margin, boxes[k].max().array() + margin};
  const Eigen::Vector2d apart =
      grown[0].min().cwiseMax(grown[1].min()) - grown[0].max().cwiseMin(grown[1].max());
  EXPECT_GE(apart.maxCoeff(), gap - 1e-12);
  const Eigen::Vector2d along = boxes[0].sizes(), across = boxes[1].sizes();
  EXPECT_GT(along.y(), 3 * along.x());    // its length along the grain now runs along y
  EXPECT_GT(across.x(), 3 * across.y());  // grain across it: its length runs along x
  // Rigid: the edge (0,0)→(3,3) keeps its length.
  EXPECT_NEAR((pieces[0].row(1) - pieces[0].row(0)).norm(), std::sqrt(18.0), 1e-12);
  EXPECT_NEAR(pieces[0](1, 0) - pieces[0](0, 0), 0.0, 1e-12);  // and runs along y
}

TEST(Layout, PackedBoxesDoNotOverlapAndKeepTheGap) {
  std::vector<Eigen::AlignedBox2d> boxes;
  for (int i = 0; i < 17; ++i)
    boxes.emplace_back(Eigen::Vector2d(-i, 3),
                       Eigen::Vector2d(-i + 1 + (i * 7) % 5, 4 + (i * 3) % 4));
  const double gap = 0.25;
  const std::vector<Eigen::Vector2d> corner = qd::flatten::shelf_pack(boxes, gap);
  for (size_t a = 0; a < boxes.size(); ++a)
    for (size_t b = a + 1; b < boxes.size(); ++b) {
      const Eigen::AlignedBox2d A(corner[a],
                                  corner[a] + boxes[a].sizes() + Eigen::Vector2d::Constant(gap));
      const Eigen::AlignedBox2d B(corner[b],
                                  corner[b] + boxes[b].sizes() + Eigen::Vector2d::Constant(gap));
      const Eigen::AlignedBox2d overlap = A.intersection(B);
      EXPECT_TRUE(overlap.isEmpty() || overlap.volume() < 1e-12) << a << " " << b;
    }
}

}  // namespace
