// Symmetric pieces: congruent copies and mirror images group within the tolerance, with the
// difference reported; larger pieces, pieces with a hole and everything at tolerance 0 stay
// alone; two mirror-image patches flattened separately group as a left/right pair.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "flatten/flatten.h"
#include "flatten/symmetric_pieces.h"
#include "flatten_meshes.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

using qd::flatten::Outline;
using qd::flatten::PatternPiece;

// A smooth outline with no symmetry (no mirror axis, not centrally symmetric), about 4 × 2.
Outline blob() {
  Outline o;
  for (int i = 0; i < 60; ++i) {
    const double t = 2 * M_PI * i / 60;
    const double r = 1 + 0.3 * std::cos(t) + 0.2 * std::sin(2 * t) + 0.1 * std::cos(3 * t + 0.5);
    o.emplace_back(2 * r * std::cos(t), r * std::sin(t));
  }
  return o;
}

// Every point mapped by `f`; reversed when `f` turns over, so the outline stays counter-clockwise.
template <typename Map>
Outline mapped(const Outline& o, bool turns_over, const Map& f) {
  Outline out;
  for (const Eigen::Vector2d& p : o) out.push_back(f(p));
  if (turns_over) std::reverse(out.begin(), out.end());
  return out;
}

PatternPiece piece(std::vector<Outline> outlines) {
  PatternPiece p;
  p.outlines = std::move(outlines);
  return p;
}

double size_of(const Outline& o) {
  Eigen::AlignedBox2d box;
  for (const Eigen::Vector2d& p : o) box.extend(p);
  return box.diagonal().norm();
}

const Eigen::Vector2d kShift(7, 3);

PatternPiece mirror_of(const Outline& o) {
  return piece({mapped(o, true, [](const Eigen::Vector2d& p) -> Eigen::Vector2d {
    return Eigen::Vector2d(-p.x(), p.y()) + kShift;
  })});
}

PatternPiece turned(const Outline& o, double degrees) {
  const Eigen::Rotation2Dd r(degrees * M_PI / 180);
  return piece({mapped(
      o, false, [&](const Eigen::Vector2d& p) -> Eigen::Vector2d { return r * p + kShift; })});
}

TEST(SymmetricPieces, MirrorImageGroupsAsMirrored) {
  const std::vector<qd::flatten::PieceGroup> g =
      qd::flatten::symmetric_groups({piece({blob()}), mirror_of(blob())}, 1);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g[0].members, (std::vector<int>{0, 1}));
  EXPECT_EQ(g[0].mirrored, (std::vector<char>{0, 1}));
  EXPECT_LT(g[0].difference, 0.01);
}

TEST(SymmetricPieces, CopyTurnedHalfWayGroupsUnmirrored) {
  const std::vector<qd::flatten::PieceGroup> g =
      qd::flatten::symmetric_groups({piece({blob()}), turned(blob(), 180)}, 1);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g[0].mirrored, (std::vector<char>{0, 0}));
  EXPECT_LT(g[0].difference, 0.01);
}

TEST(SymmetricPieces, SlightTurnIsFittedButALargeOneIsNot) {
  // Turned by 2°, the copy's far end moves by more than the 1 % tolerance: only the fit's
  // refinement brings it within.
  const Outline o = blob();
  double reach = 0;
  for (const Eigen::Vector2d& p : o) reach = std::max(reach, p.norm());
  ASSERT_GT(2 * std::sin(M_PI / 180) * reach, 0.01 * size_of(o));
  const std::vector<qd::flatten::PieceGroup> slight =
      qd::flatten::symmetric_groups({piece({o}), turned(o, 2)}, 1);
  ASSERT_EQ(slight.size(), 1u);
  EXPECT_LT(slight[0].difference, 0.05);
  // 30° off would put the grain off: not the same piece to cut, whatever the tolerance.
  EXPECT_EQ(qd::flatten::symmetric_groups({piece({o}), turned(o, 30)}, 5).size(), 2u);
}

TEST(SymmetricPieces, LargerPieceGroupsOnlyAtALargeTolerance) {
  const Outline o = blob();
  const std::vector<PatternPiece> pieces = {
      piece({o}), piece({mapped(o, false, [](const Eigen::Vector2d& p) -> Eigen::Vector2d {
        return 1.05 * p;
      })})};
  EXPECT_EQ(qd::flatten::symmetric_groups(pieces, 1).size(), 2u);
  const std::vector<qd::flatten::PieceGroup> loose = qd::flatten::symmetric_groups(pieces, 10);
  ASSERT_EQ(loose.size(), 1u);
  EXPECT_GT(loose[0].difference, 1.0);
  EXPECT_LT(loose[0].difference, 10.0);
}

TEST(SymmetricPieces, SmallPerturbationGroupsWithItsSizeReported) {
  const Outline o = blob();
  const double amplitude = 0.002 * size_of(o);
  std::mt19937 random(26);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  const Outline noisy = mapped(o, false, [&](const Eigen::Vector2d& p) -> Eigen::Vector2d {
    const double a = angle(random);
    return p + amplitude * Eigen::Vector2d(std::cos(a), std::sin(a));
  });
  const std::vector<qd::flatten::PieceGroup> g =
      qd::flatten::symmetric_groups({piece({o}), piece({noisy})}, 1);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_GT(g[0].difference, 0.05);
  EXPECT_LT(g[0].difference, 1.0);
}

TEST(SymmetricPieces, ZeroToleranceLeavesEveryPieceAlone) {
  const std::vector<qd::flatten::PieceGroup> g =
      qd::flatten::symmetric_groups({piece({blob()}), piece({blob()})}, 0);
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[0].members, (std::vector<int>{0}));
  EXPECT_EQ(g[1].members, (std::vector<int>{1}));
  EXPECT_EQ(g[1].mirrored, (std::vector<char>{0}));
}

// Above the bound every piece stays alone (the search is quadratic); at it, copies still group.
TEST(SymmetricPieces, ManyPiecesAreLeftAloneAboveTheBound) {
  const std::vector<PatternPiece> at(qd::flatten::kMaxSymmetryPieces,
                                     piece({{{0, 0}, {1, 0}, {0, 2}}}));
  EXPECT_EQ(qd::flatten::symmetric_groups(at, 1).size(), 1u);
  std::vector<PatternPiece> above = at;
  above.push_back(at.front());
  EXPECT_EQ(qd::flatten::symmetric_groups(above, 1).size(), above.size());
}

TEST(SymmetricPieces, ThreeCopiesAreOneGroupInIndexOrder) {
  const Outline o = blob();
  const PatternPiece other =
      piece({mapped(o, false, [](const Eigen::Vector2d& p) -> Eigen::Vector2d {
        return Eigen::Vector2d(p.x(), 2 * p.y());
      })});
  const std::vector<PatternPiece> pieces = {mirror_of(o), other, piece({o}), turned(o, 180)};
  const std::vector<qd::flatten::PieceGroup> g = qd::flatten::symmetric_groups(pieces, 1);
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[0].members, (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(g[0].mirrored, (std::vector<char>{0, 1, 1}));
  EXPECT_EQ(g[1].members, (std::vector<int>{1}));
  const std::vector<qd::flatten::PieceGroup> again = qd::flatten::symmetric_groups(pieces, 1);
  ASSERT_EQ(again.size(), g.size());
  for (size_t k = 0; k < g.size(); ++k) {
    EXPECT_EQ(again[k].members, g[k].members);
    EXPECT_EQ(again[k].mirrored, g[k].mirrored);
    EXPECT_EQ(again[k].difference, g[k].difference);  // the same computation, bit for bit
  }
}

TEST(SymmetricPieces, PieceJoinsTheRepresentativeItFitsBest) {
  // Scaled by 1, 1.04 and 1.025: the first two are too far apart to group at 1.5 %, the third
  // fits both and is closer to the second.
  const Outline o = blob();
  std::vector<PatternPiece> pieces;
  for (double scale : {1.0, 1.04, 1.025})
    pieces.push_back(piece({mapped(
        o, false, [&](const Eigen::Vector2d& p) -> Eigen::Vector2d { return scale * p; })}));
  ASSERT_EQ(qd::flatten::symmetric_groups({pieces[0], pieces[2]}, 1.5).size(), 1u);
  const std::vector<qd::flatten::PieceGroup> g = qd::flatten::symmetric_groups(pieces, 1.5);
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[0].members, (std::vector<int>{0}));
  EXPECT_EQ(g[1].members, (std::vector<int>{1, 2}));
}

TEST(SymmetricPieces, PieceWithAHoleNeverGroupsWithOneWithout) {
  const Outline o = blob();
  const Outline hole =
      mapped(o, true, [](const Eigen::Vector2d& p) -> Eigen::Vector2d { return 0.05 * p; });
  EXPECT_EQ(qd::flatten::symmetric_groups({piece({o, hole}), piece({o})}, 50).size(), 2u);
  EXPECT_EQ(qd::flatten::symmetric_groups({piece({o, hole}), piece({o, hole})}, 1).size(), 1u);
}

// A left patch and its mirror image in x, meshed with the other diagonals, flattened separately:
// the pattern pieces (turned by their principal axis on the sheet) group as a mirrored pair. The
// patch is a slanted strip of a bumpy cone, elongated so its principal axis is well defined, and
// without symmetry.
TEST(SymmetricPieces, MirrorImagePatchesFlattenIntoAMirroredPair) {
  const auto left = [](int i, int j) {
    const double t = 1.5 * i / 24, s = static_cast<double>(j) / 8;
    const double r =
        1 + 0.5 * s + 0.1 * std::exp(-(std::pow(t - 0.4, 2) + std::pow(s - 0.3, 2)) / 0.05);
    return qd::common::Vec3(3 + r * std::cos(t), r * std::sin(t), (0.8 + 0.3 * t) * s);
  };
  // Columns run the other way, so the faces keep their orientation and the quads are split
  // along their other diagonal.
  const qd::test::GridMesh a = qd::test::grid_mesh(24, 8, false, left);
  const qd::test::GridMesh b = qd::test::grid_mesh(24, 8, false, [&](int i, int j) {
    const qd::common::Vec3 p = left(24 - i, j);
    return qd::common::Vec3(-p.x(), p.y(), p.z());
  });
  qd::flatten::FlattenProblem problem;
  const int nv = static_cast<int>(a.V.rows()), nf = static_cast<int>(a.F.rows());
  problem.V.resize(2 * nv, 3);
  problem.V << a.V, b.V;
  problem.F.resize(2 * nf, 3);
  problem.F << a.F, b.F.array() + nv;
  problem.patch.assign(nf, 0);
  problem.patch.resize(2 * nf, 1);
  const qd::flatten::FlattenResult r =
      qd::flatten::flatten(problem);  // symmetry_tolerance 1 % by default
  ASSERT_EQ(r.pieces.size(), 2u);
  const std::vector<qd::flatten::PieceGroup>& g = r.groups;
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g[0].mirrored, (std::vector<char>{0, 1}));
  EXPECT_LT(g[0].difference, 1.0);
  ASSERT_EQ(r.pattern.pieces.size(), 1u);  // one pattern piece, cut twice, once turned over
  EXPECT_EQ(r.pattern.pieces[0].quantity, 2);
  EXPECT_EQ(r.pattern.pieces[0].mirrored, 1);
  EXPECT_NE(std::find_if(r.log.begin(), r.log.end(),
                         [](const std::string& line) {
                           return line.find("one pattern piece, cut 2") != std::string::npos;
                         }),
            r.log.end());
  RecordProperty("difference_percent", std::to_string(g[0].difference));
}

}  // namespace
