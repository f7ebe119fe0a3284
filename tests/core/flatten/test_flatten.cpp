// The whole flattening: curved patches are flattened anyway with their distortion reported
// truthfully, the result is deterministic for any number of threads, progress is reported,
// pieces lie apart on the sheet, notches mark seams, bad input fails clearly.
#include <gtest/gtest.h>

#include <functional>

#include "common/error.h"
#include "flatten/face_distortion.h"
#include "flatten/flat_triangles.h"
#include "flatten/flatten.h"
#include "flatten_meshes.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

using qd::test::GridMesh;

qd::flatten::FlattenProblem problem_of(const GridMesh& m, int threads = 0) {
  qd::flatten::FlattenProblem p;
  p.V = m.V;
  p.F = m.F;
  p.patch = m.patch;
  p.params.threads = threads;
  return p;
}

// A bumpy tube (doubly curved where the bumps are) in four patches by angular sector, plus an
// open cone strip as a fifth patch: seams, a tube-free mix and parallel work.
GridMesh five_patches() {
  GridMesh m = qd::test::grid_mesh(32, 10, false, [](int i, int j) {
    const double t = 1.6 * M_PI * i / 32, z = 2.0 * j / 10;
    const double r = 1 + 0.15 * std::exp(-(std::pow(t - 2.0, 2) + std::pow(z - 1.0, 2)) / 0.2);
    return qd::common::Vec3(r * std::cos(t), r * std::sin(t), z);
  });
  for (int f = 0; f < m.F.rows(); ++f) m.patch.push_back((f / 2) % 32 / 8);
  const GridMesh cone = qd::test::cone(16, 4, 1.0, 0.5, 1.0, 2.0);
  const int nv = static_cast<int>(m.V.rows()), nf = static_cast<int>(m.F.rows());
  m.V.conservativeResize(nv + cone.V.rows(), 3);
  m.V.bottomRows(cone.V.rows()) = cone.V.rowwise() + Eigen::RowVector3d(5, 0, 0);
  m.F.conservativeResize(nf + cone.F.rows(), 3);
  m.F.bottomRows(cone.F.rows()) = cone.F.array() + nv;
  m.patch.resize(static_cast<size_t>(m.F.rows()), 9);
  return m;
}

TEST(Flatten, DoublyCurvedCapIsFlattenedWithItsDistortionReported) {
  const GridMesh cap = qd::test::spherical_cap(32, 12, 1.2);  // about 69° from the pole
  const qd::flatten::FlattenResult r = qd::flatten::flatten(problem_of(cap));
  ASSERT_EQ(r.pieces.size(), 1u);
  const qd::flatten::PieceReport& p = r.pieces[0];
  EXPECT_GT(p.max_distortion, 5.0);
  EXPECT_GT(p.mean_distortion, 1.0);
  EXPECT_TRUE(r.uv.allFinite());
  // The report agrees with the texture coordinates it hands back: the faces measured again on
  // their own corners (face f's corners are rows 3f, 3f + 1, 3f + 2).
  const qd::flatten::FlatTriangles g = qd::flatten::flat_triangles(cap.V, cap.F);
  qd::common::Triangles corners(cap.F.rows(), 3);
  Eigen::MatrixX2d uv(3 * cap.F.rows(), 2);
  for (int f = 0; f < cap.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      corners(f, k) = 3 * f + k;
      uv.row(3 * f + k) = r.uv.block<1, 2>(f, 2 * k);
    }
  double worst = 0;
  int flipped = 0;
  for (int f = 0; f < cap.F.rows(); ++f) {
    const qd::flatten::Stretch s =
        qd::flatten::stretch(qd::flatten::face_jacobian(g, corners, uv, f));
    worst = std::max(worst, qd::flatten::length_distortion(s));
    flipped += s.flipped;
    EXPECT_NEAR(r.stretch[f], qd::flatten::signed_stretch(s), 1e-12);
  }
  EXPECT_NEAR(p.max_distortion, 100 * worst, 1e-9);
  EXPECT_EQ(p.flipped, flipped);
  EXPECT_NE(r.log[0].find("length distortion max"), std::string::npos);
}

TEST(Flatten, RampThatDevelopsOntoItselfIsReportedNotFlattenable) {
  // The tangent developable of a helix (pitch 0.3 per radian) over three turns: developable,
  // but its development winds about 2.9 times around the circle its edge of regression becomes.
  const GridMesh ramp = qd::test::grid_mesh(240, 4, false, [](int i, int j) {
    const double t = 6 * M_PI * i / 240, b = 0.3, s = (0.4 + 0.2 * j) / std::sqrt(1 + b * b);
    return qd::common::Vec3(std::cos(t) - s * std::sin(t), std::sin(t) + s * std::cos(t),
                            b * (t + s));
  });
  const qd::flatten::FlattenResult r = qd::flatten::flatten(problem_of(ramp));
  ASSERT_EQ(r.pieces.size(), 1u);
  const qd::flatten::PieceReport& p = r.pieces[0];
  EXPECT_GT(p.overlapping, 0);
  EXPECT_FALSE(p.flattenable);
  EXPECT_NE(r.log[0].find("not flattenable without a cut"), std::string::npos);
  EXPECT_LT(p.max_distortion, 1.0);  // still flattened, and nearly isometric
  EXPECT_TRUE(r.uv.allFinite());
}

TEST(Flatten, SameResultTwiceAndForAnyNumberOfThreads) {
  const GridMesh m = five_patches();
  const qd::flatten::FlattenResult a = qd::flatten::flatten(problem_of(m, 1));
  const qd::flatten::FlattenResult b = qd::flatten::flatten(problem_of(m, 1));
  const qd::flatten::FlattenResult c = qd::flatten::flatten(problem_of(m, 3));
  ASSERT_EQ(a.pieces.size(), 5u);
  EXPECT_EQ(a.uv, b.uv);
  EXPECT_EQ(a.uv, c.uv);
  EXPECT_EQ(a.stretch, c.stretch);
  for (size_t i = 0; i < a.pieces.size(); ++i) {
    EXPECT_EQ(a.pieces[i].iterations, c.pieces[i].iterations);
    EXPECT_EQ(a.log[i], c.log[i]);
  }
}

TEST(Flatten, PiecesLieApartAndSeamsGetNotches) {
  const GridMesh m = five_patches();
  qd::flatten::FlattenProblem problem = problem_of(m);
  problem.params.notch_spacing = 0.5;
  problem.params.symmetry_tolerance = 0;  // patches 1 and 2 are congruent: keep one piece each
  const qd::flatten::FlattenResult r = qd::flatten::flatten(problem);
  ASSERT_EQ(r.pieces.size(), 5u);
  for (size_t a = 0; a < r.pieces.size(); ++a) {
    EXPECT_EQ(r.pieces[a].flipped, 0);
    EXPECT_EQ(r.pieces[a].overlapping, 0);
    for (size_t b = a + 1; b < r.pieces.size(); ++b)
      EXPECT_TRUE(r.pieces[a].box.intersection(r.pieces[b].box).isEmpty()) << a << " " << b;
  }
  // Seams run up a vertex column of length 2: notches at both ends and every 0.5 between.
  // Patches 0 and 3 have one seam, 1 and 2 two, the cone none.
  ASSERT_EQ(r.pattern.pieces.size(), 5u);
  const std::vector<size_t> notches = {5, 10, 10, 5, 0};
  for (size_t i = 0; i < 5; ++i) EXPECT_EQ(r.pattern.pieces[i].notches.size(), notches[i]) << i;
  EXPECT_EQ(r.pattern.pieces[4].label, "9");
  // Texture coordinates lie in the piece's box.
  for (int f = 0; f < m.F.rows(); ++f) {
    const size_t piece = m.patch[f] == 9 ? 4 : static_cast<size_t>(m.patch[f]);
    for (int k = 0; k < 3; ++k)
      EXPECT_TRUE(
          r.pieces[piece].box.contains(Eigen::Vector2d(r.uv.block<1, 2>(f, 2 * k).transpose())));
  }
}

TEST(Flatten, OneTrianglePatchesAreExactPieces) {
  GridMesh m = qd::test::cylinder(8, 2, 1.0, 1.0);
  m.patch.assign(static_cast<size_t>(m.F.rows()), 0);
  m.patch[5] = 1;  // a single triangle
  m.patch[6] = 2;  // and another one beside it: they share an edge but not a patch
  const qd::flatten::FlattenResult r = qd::flatten::flatten(problem_of(m));
  ASSERT_EQ(r.pieces.size(), 3u);
  for (int piece = 1; piece <= 2; ++piece) {
    EXPECT_EQ(r.pieces[piece].faces, 1);
    EXPECT_LT(r.pieces[piece].max_distortion, 1e-9);
  }
  EXPECT_EQ(r.pieces[0].faces, 30);  // still a tube, whose two loops the notch does not join
  EXPECT_NE(r.pieces[0].cut.find("1 shortest path"), std::string::npos) << r.pieces[0].cut;
  EXPECT_LT(r.pieces[0].max_distortion, 1e-6);
}

TEST(Flatten, ProgressRisesToOneHundred) {
  std::vector<int> percent;
  qd::flatten::flatten(problem_of(five_patches(), 1),
                       [&](int p, const std::string&) { percent.push_back(p); });
  ASSERT_FALSE(percent.empty());
  EXPECT_TRUE(std::is_sorted(percent.begin(), percent.end()));
  EXPECT_EQ(percent.back(), 100);
}

TEST(Flatten, BadInputFailsWithAReason) {
  qd::flatten::FlattenProblem empty;
  EXPECT_THROW(qd::flatten::flatten(empty), qd::common::Error);
  for (const auto& bad : std::vector<std::function<void(qd::flatten::FlattenParams&)>>{
           [](qd::flatten::FlattenParams& q) { q.max_iterations = -1; },
           [](qd::flatten::FlattenParams& q) { q.tolerance = NAN; },
           [](qd::flatten::FlattenParams& q) { q.gap = -1; },
           [](qd::flatten::FlattenParams& q) { q.notch_spacing = INFINITY; },
           [](qd::flatten::FlattenParams& q) { q.threads = -2; }}) {
    qd::flatten::FlattenProblem p = problem_of(qd::test::cylinder(8, 2, 1, 1, 2));
    bad(p.params);
    EXPECT_THROW(qd::flatten::flatten(p), qd::common::Error);
  }
  qd::flatten::FlattenProblem nan = problem_of(qd::test::cylinder(8, 2, 1, 1, 2));
  nan.V(3, 1) = NAN;
  try {
    qd::flatten::flatten(nan);
    FAIL();
  } catch (const qd::common::Error& e) {
    EXPECT_NE(std::string(e.what()).find("NaN"), std::string::npos) << e.what();
  }
}

}  // namespace
