// Grainline: the model's up direction carried onto the flat piece, the principal axis where
// up says little, always a unit vector; a flattened cylinder panel is laid out with its axis
// along the grain.
#include <gtest/gtest.h>

#include <cmath>

#include "flatten/flatten.h"
#include "flatten/grainline.h"
#include "flatten_meshes.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

Eigen::Matrix2d turn(double angle) { return Eigen::Rotation2Dd(angle).toRotationMatrix(); }

TEST(Grainline, CylinderPanelGrainRunsAlongItsAxis) {
  const double r = 1, h = 3, sweep = 2.0;
  const qd::test::GridMesh panel = qd::test::cylinder(12, 6, r, h, sweep);
  // Its development (arc length, height), turned by 0.7 rad: the axis z maps to turn(0.7)·y.
  Eigen::MatrixX2d uv(panel.V.rows(), 2);
  for (int v = 0; v < uv.rows(); ++v) {
    const double arc = r * std::atan2(panel.V(v, 1), panel.V(v, 0));
    uv.row(v) = (turn(0.7) * Eigen::Vector2d(arc, panel.V(v, 2))).transpose();
  }
  const Eigen::Vector2d grain =
      qd::flatten::grain_direction(panel.V, panel.F, uv, Eigen::Vector3d(0, 0, 2));
  EXPECT_NEAR(grain.norm(), 1, 1e-12);
  EXPECT_NEAR((grain - turn(0.7) * Eigen::Vector2d::UnitY()).norm(), 0, 1e-3);
}

// A zero direction asks for the longest axis whatever way up points: a panel 2 wide (sweep 2 of
// radius 1) and 3 tall gets its grain along the axis; 6 wide and 3 tall, across it.
TEST(Grainline, ZeroDirectionTakesEveryPiecesLongestAxis) {
  for (const auto& [sweep, along] : {std::pair{2.0, true}, std::pair{6.0, false}}) {
    const qd::test::GridMesh panel = qd::test::cylinder(24, 6, 1, 3, sweep);
    Eigen::MatrixX2d uv(panel.V.rows(), 2);
    for (int v = 0; v < uv.rows(); ++v)
      uv.row(v) =
          Eigen::Vector2d(std::atan2(panel.V(v, 1), panel.V(v, 0)), panel.V(v, 2)).transpose();
    const Eigen::Vector2d grain =
        qd::flatten::grain_direction(panel.V, panel.F, uv, Eigen::Vector3d::Zero());
    EXPECT_NEAR(std::abs(grain.y()), along ? 1 : 0, 1e-6) << sweep;
  }
}

TEST(Grainline, HorizontalDiscFallsBackToItsLongestAxis) {
  // An elliptic disc in the plane z = 0, three times longer along x, laid out turned by 0.5.
  qd::test::GridMesh disc = qd::test::grid_mesh(24, 4, true, [](int i, int j) {
    const double t = 2 * M_PI * i / 24, s = (j + 1) / 5.0;
    return qd::common::Vec3(3 * s * std::cos(t), s * std::sin(t), 0);
  });
  Eigen::MatrixX2d uv = disc.V.leftCols<2>() * turn(0.5).transpose();
  const Eigen::Vector2d grain =
      qd::flatten::grain_direction(disc.V, disc.F, uv, Eigen::Vector3d::UnitZ());
  EXPECT_NEAR(grain.norm(), 1, 1e-12);
  EXPECT_NEAR(std::abs(grain.dot(turn(0.5) * Eigen::Vector2d::UnitX())), 1, 1e-9);
  // Tilted 10° about y: up still says too little (sin 10° < kWeakGrain), and the fallback
  // points the way up leans (up's projection runs along x' on the tilted disc).
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd(10 * M_PI / 180, Eigen::Vector3d::UnitY()).toRotationMatrix();
  disc.V = disc.V * tilt.transpose();
  const Eigen::Vector2d tilted =
      qd::flatten::grain_direction(disc.V, disc.F, uv, Eigen::Vector3d::UnitZ());
  EXPECT_NEAR(tilted.norm(), 1, 1e-12);
  EXPECT_NEAR(std::abs(tilted.dot(grain)), 1, 1e-9);
}

TEST(Grainline, FlattenedCylinderPanelIsLaidWithItsAxisUpTheSheet) {
  const qd::test::GridMesh panel = qd::test::cylinder(16, 8, 1.0, 0.8, 2.5);  // wider than tall
  qd::flatten::FlattenProblem problem;
  problem.V = panel.V;
  problem.F = panel.F;
  problem.params.grain_up = Eigen::Vector3d::UnitZ();
  const qd::flatten::FlattenResult r = qd::flatten::flatten(problem);
  ASSERT_EQ(r.pattern.pieces.size(), 1u);
  const qd::flatten::PatternPiece& p = r.pattern.pieces[0];
  EXPECT_NEAR((p.grain - Eigen::Vector2d::UnitY()).norm(), 0, 1e-12);
  // The axis (height 0.8) runs along y, the unrolled width (2.5 minus chords) along x.
  EXPECT_NEAR(r.pieces[0].box.sizes().y(), 0.8, 1e-3);
  EXPECT_GT(r.pieces[0].box.sizes().x(), 2.4);
  // The bottom edge (z = 0) lies at the bottom of the sheet: the grain points up, not down.
  for (int f = 0; f < problem.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (problem.V(problem.F(f, k), 2) == 0) {
        EXPECT_NEAR(r.uv(f, 2 * k + 1), r.pieces[0].box.min().y(), 1e-3);
      }
}

}  // namespace
