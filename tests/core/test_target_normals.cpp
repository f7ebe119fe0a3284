// Step 1 end to end: fit_targets on Gauss images with known skeleton curves.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>

#include "approximate/target_normals.h"
#include "common/error.h"
#include "common/parallel_for.h"
#include "test_gauss_samples.h"

using namespace qd_test;

namespace {

using namespace qd::approximate;
using namespace qd::common;

// Largest angle (degrees) between a target and the great circle with pole `axis`.
double max_off_great_circle_deg(const std::vector<Vec3>& targets, const Vec3& axis) {
  double worst = 0;
  for (const Vec3& t : targets) worst = std::max(worst, std::abs(std::asin(t.dot(axis))));
  return worst / kDeg;
}

void expect_unit(const std::vector<Vec3>& v) {
  for (const Vec3& t : v) {
    ASSERT_TRUE(t.allFinite());
    EXPECT_NEAR(t.norm(), 1.0, 1e-12);
  }
}

}  // namespace

TEST(TargetNormals, CylinderGivesGreatCircleWithSmallResidual) {
  const Vec3 axis = Vec3(0.3, -0.5, 0.8).normalized();
  const Samples s = cylinder(axis, 0.2, 0.2 + 100 * kDeg, 2000, 1.0 * kDeg, 20);
  const qd::approximate::TargetFit fit = qd::approximate::fit_targets(s.normals, s.areas);
  EXPECT_EQ(fit.model->kind(), qd::approximate::TargetKind::Curve);
  expect_unit(fit.targets);
  const std::vector<Vec3> inliers(fit.targets.begin(), fit.targets.begin() + 2000);
  EXPECT_LT(max_off_great_circle_deg(inliers, axis), 0.5);
  // Noise 1° per tangent component: mean |off-circle angle| ≈ 0.8°; outliers add a little.
  EXPECT_LT(fit.residual_deg, 1.5);
  EXPECT_GT(fit.residual_deg, 0.3);
  // A target is the nearest point: it keeps the sample's azimuth around the axis (away from
  // the arc's ends, where noisy samples beyond the end project onto it).
  const Eigen::Matrix3d F = frame_for(axis);
  for (size_t i = 0; i < 2000; ++i) {
    const Vec3 local = F.transpose() * s.normals[i];
    const double azimuth = std::atan2(local.y(), local.x());
    if (azimuth < 0.2 + 3 * kDeg || azimuth > 0.2 + 97 * kDeg) continue;
    const Vec3 a = (s.normals[i] - s.normals[i].dot(axis) * axis).normalized();
    EXPECT_LT(angle(a, fit.targets[i]), 0.5 * kDeg);
  }
}

TEST(TargetNormals, ConeGivesSmallCircleAtTheRightAngle) {
  for (double beta_deg : {40.0, 65.0, 110.0}) {
    const Vec3 axis = Vec3(-0.2, 0.9, 0.1).normalized();
    const Samples s = cone(axis, beta_deg * kDeg, 1.0, 1.0 + 150 * kDeg, 1500, 0.5 * kDeg);
    const qd::approximate::TargetFit fit = qd::approximate::fit_targets(s.normals, s.areas);
    for (const Vec3& t : fit.targets)
      EXPECT_NEAR(angle(t, axis) / kDeg, beta_deg, 0.6) << "beta " << beta_deg;
    EXPECT_LT(fit.residual_deg, 1.0);
  }
}

TEST(TargetNormals, SShapedCurveIsFollowed) {
  const Eigen::Matrix3d F = random_rotation(3);
  auto phi = [](double t) { return kPi / 2 + 20 * kDeg * std::sin(2.5 * t); };
  const Samples s = curve_samples(F, 0.0, 150 * kDeg, phi, 3000, 0.7 * kDeg, 30);
  const qd::approximate::TargetFit fit = qd::approximate::fit_targets(s.normals, s.areas);
  // Dense copy of the true curve.
  std::vector<Vec3> truth;
  for (int k = 0; k <= 6000; ++k) {
    const double t = 150 * kDeg * k / 6000.0;
    truth.push_back(
        F * Vec3(std::sin(phi(t)) * std::cos(t), std::sin(phi(t)) * std::sin(t), std::cos(phi(t))));
  }
  // Every target lies on the true curve (or its prolongation past the ends, where noisy end
  // samples may legitimately project): check the targets of samples away from the ends.
  double worst = 0;
  for (size_t i = 0; i < 3000; ++i) {
    double best = 1e9;
    size_t at = 0;
    for (size_t k = 0; k < truth.size(); ++k)
      if (angle(s.normals[i], truth[k]) < best) best = angle(s.normals[i], truth[k]), at = k;
    if (at < 100 || at + 100 > truth.size()) continue;  // within 2.5° of an end
    best = 1e9;
    for (const Vec3& c : truth) best = std::min(best, angle(fit.targets[i], c));
    worst = std::max(worst, best);
  }
  EXPECT_LT(worst / kDeg, 0.5);
  EXPECT_LT(fit.residual_deg, 1.2);
}

TEST(TargetNormals, TubeGivesClosedCurveWithoutCutAtSeam) {
  const Vec3 axis = Vec3(1, 2, 2).normalized();
  const Samples s = cylinder(axis, 0.0, 2 * kPi, 3000, 1.0 * kDeg);
  const qd::approximate::TargetFit fit = qd::approximate::fit_targets(s.normals, s.areas);
  EXPECT_EQ(fit.model->kind(), qd::approximate::TargetKind::ClosedCurve);
  EXPECT_LT(max_off_great_circle_deg(fit.targets, axis), 0.5);
  // No cut anywhere: every target keeps its sample's azimuth (a cut would pull the samples
  // of the gap to the curve's ends).
  double worst = 0;
  for (size_t i = 0; i < s.normals.size(); ++i) {
    const Vec3 a = (s.normals[i] - s.normals[i].dot(axis) * axis).normalized();
    worst = std::max(worst, angle(a, fit.targets[i]));
  }
  EXPECT_LT(worst / kDeg, 0.5);
  // And every azimuth is reached by the model (probe 720 directions on the circle).
  const Eigen::Matrix3d F = frame_for(axis);
  for (int k = 0; k < 720; ++k) {
    const Vec3 n = F * Vec3(std::cos(k * kPi / 360), std::sin(k * kPi / 360), 0);
    EXPECT_LT(angle(fit.model->project(n), n) / kDeg, 0.5);
  }
}

TEST(TargetNormals, CoarseTubeOfSixteenFacetsIsClosed) {
  // A 16-sided prism: 16 clusters of identical normals 22.5° apart.
  const Eigen::Matrix3d F = frame_for(Vec3(0.2, 0.1, 1));
  qd_test::Samples s;
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 10; ++j) {
      s.normals.push_back(F * Vec3(std::cos(k * kPi / 8), std::sin(k * kPi / 8), 0));
      s.areas.push_back(1.0);
    }
  const qd::approximate::TargetFit fit = qd::approximate::fit_targets(s.normals, s.areas);
  EXPECT_EQ(fit.model->kind(), qd::approximate::TargetKind::ClosedCurve);
  EXPECT_LT(fit.residual_deg, 0.5);  // a cut at the seam would leave 22.5° unfitted
}

TEST(TargetNormals, PlanarPatchGivesPlaneModel) {
  const Vec3 n0 = Vec3(0.4, 0.4, -0.8).normalized();
  const Samples s = curve_samples(
      frame_for(n0), 0, 0, [](double) { return 0.0; }, 500, 0.3 * kDeg);
  const qd::approximate::TargetFit fit = qd::approximate::fit_targets(s.normals, s.areas);
  EXPECT_EQ(fit.model->kind(), qd::approximate::TargetKind::Plane);
  Vec3 mean = Vec3::Zero();
  for (size_t i = 0; i < s.normals.size(); ++i) mean += s.areas[i] * s.normals[i];
  for (const Vec3& t : fit.targets) EXPECT_LT((t - mean.normalized()).norm(), 1e-12);
}

TEST(TargetNormals, SphereFillingNormalsThrow) {
  const Samples s = curve_samples(
      Eigen::Matrix3d::Identity(), 0, 0, [](double) { return 0.0; }, 0, 0.0, 2000);
  try {
    qd::approximate::fit_targets(s.normals, s.areas);
    FAIL() << "expected qd::common::Error";
  } catch (const qd::common::Error& e) {
    EXPECT_NE(std::string(e.what()).find("fill the sphere"), std::string::npos) << e.what();
  }
}

TEST(TargetNormals, HemisphereBowlDoesNotThrow) {
  // Normals of a spherical cap of 90°: uniform over a hemisphere (area-uniform: cos φ uniform).
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  qd_test::Samples s;
  for (int i = 0; i < 2000; ++i) {
    const double z = u(rng), t = 2 * kPi * u(rng), r = std::sqrt(1 - z * z);
    s.normals.push_back(Vec3(r * std::cos(t), r * std::sin(t), z));
    s.areas.push_back(1.0);
  }
  const qd::approximate::TargetFit fit = qd::approximate::fit_targets(s.normals, s.areas);
  expect_unit(fit.targets);
  EXPECT_GT(fit.residual_deg, 5.0);  // far from developable, reported as such
}

TEST(TargetNormals, RotationEquivariant) {
  auto phi = [](double t) { return kPi / 2 + 15 * kDeg * std::sin(3 * t); };
  const std::vector<Samples> cases = {
      curve_samples(random_rotation(11), 0.0, 140 * kDeg, phi, 1000, 0.8 * kDeg, 10),
      cylinder(Vec3(0, 1, 1), 0.0, 2 * kPi, 1000, 0.8 * kDeg),
      cone(Vec3(1, 0, 0), 50 * kDeg, 0.0, 200 * kDeg, 1000, 0.5 * kDeg)};
  for (size_t c = 0; c < cases.size(); ++c) {
    const qd::approximate::TargetFit a =
        qd::approximate::fit_targets(cases[c].normals, cases[c].areas);
    for (unsigned seed : {21u, 22u, 23u}) {
      const Eigen::Matrix3d Q = random_rotation(seed);
      std::vector<Vec3> rotated;
      for (const Vec3& n : cases[c].normals) rotated.push_back(Q * n);
      const qd::approximate::TargetFit b = qd::approximate::fit_targets(rotated, cases[c].areas);
      EXPECT_EQ(a.model->kind(), b.model->kind());
      double worst = 0;
      for (size_t i = 0; i < rotated.size(); ++i)
        worst = std::max(worst, (Q * a.targets[i] - b.targets[i]).norm());
      EXPECT_LT(worst, 1e-9) << "case " << c << " seed " << seed;
      EXPECT_NEAR(a.residual_deg, b.residual_deg, 1e-9);
    }
  }
}

TEST(TargetNormals, DeterministicAndProjectMatchesTargets) {
  const Samples s = cone(Vec3(0, 0, 1), 70 * kDeg, 0.0, 120 * kDeg, 800, 0.5 * kDeg);
  const qd::approximate::TargetFit a = qd::approximate::fit_targets(s.normals, s.areas);
  const qd::approximate::TargetFit b = qd::approximate::fit_targets(s.normals, s.areas);
  for (size_t i = 0; i < s.normals.size(); ++i) {
    EXPECT_EQ(a.targets[i], b.targets[i]);
    EXPECT_EQ(a.model->project(s.normals[i]), a.targets[i]);
  }
}

TEST(TargetNormals, HintDoesNotChangeTheProjection) {
  // Noisy samples along an S-shaped open curve, a closed tube and a cone: projections chained
  // through the hint (in sample order and shuffled, so hints are near and far) equal the
  // projections without one, bit for bit.
  auto phi = [](double t) { return kPi / 2 + 20 * kDeg * std::sin(2.5 * t); };
  const std::vector<Samples> cases = {
      curve_samples(random_rotation(7), 0.0, 150 * kDeg, phi, 2000, 3.0 * kDeg, 20),
      cylinder(Vec3(1, 2, 2).normalized(), 0.0, 2 * kPi, 2000, 2.0 * kDeg),
      cone(Vec3(0, 1, 0), 60 * kDeg, 0.0, 90 * kDeg, 2000, 0.5 * kDeg)};
  for (size_t c = 0; c < cases.size(); ++c) {
    const std::vector<Vec3>& normals = cases[c].normals;
    const qd::approximate::TargetFit fit = qd::approximate::fit_targets(normals, cases[c].areas);
    std::vector<size_t> order(normals.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    for (int pass = 0; pass < 2; ++pass) {
      int hint = -1;
      for (size_t i : order) {
        EXPECT_EQ(fit.model->project(normals[i], hint), fit.model->project(normals[i]))
            << "case " << c << " sample " << i;
        EXPECT_EQ(fit.targets[i], fit.model->project(normals[i]));
      }
      std::shuffle(order.begin(), order.end(), std::mt19937(static_cast<unsigned>(c)));
    }
  }
}

TEST(TargetNormals, ThreadsDoNotChangeTheTargets) {
  // More samples than one range of the parallel projection (kRangeChunk), so the ranges start
  // without a hint on different threads.
  const Samples s = cylinder(Vec3(1, 2, 2).normalized(), 0.0, 2 * kPi, 10000, 2.0 * kDeg);
  ASSERT_GT(s.normals.size(), 2 * qd::common::kRangeChunk);
  const qd::approximate::TargetFit one = qd::approximate::fit_targets(s.normals, s.areas, 1);
  const qd::approximate::TargetFit two = qd::approximate::fit_targets(s.normals, s.areas, 2);
  EXPECT_EQ(one.residual_deg, two.residual_deg);
  EXPECT_EQ(qd::approximate::project_normals(*one.model, s.normals, 2), two.targets);
  for (size_t i = 0; i < s.normals.size(); ++i) {
    EXPECT_EQ(one.targets[i], two.targets[i]) << "sample " << i;
    EXPECT_EQ(two.targets[i], one.model->project(s.normals[i])) << "sample " << i;
  }
}

TEST(TargetNormals, ProjectionIsTheNearestPointOfTheCurve) {
  const Samples s = cone(Vec3(0, 1, 0), 60 * kDeg, 0.0, 90 * kDeg, 1000, 0.5 * kDeg);
  const qd::approximate::TargetFit fit = qd::approximate::fit_targets(s.normals, s.areas);
  // Densely sample the model's curve by projecting a fan of directions, then check that no
  // curve point is nearer to a sample than its target (up to the refinement tolerance).
  std::vector<Vec3> curve;
  for (const Vec3& n : s.normals) curve.push_back(fit.model->project(n));
  for (size_t i = 0; i < s.normals.size(); i += 7) {
    const double mine = angle(s.normals[i], fit.targets[i]);
    for (const Vec3& c : curve) EXPECT_GE(angle(s.normals[i], c), mine - 1e-9);
  }
}

TEST(TargetNormals, ZeroAreaSamplesWeighNothing) {
  Samples s = cylinder(Vec3(1, 0, 0), 0.0, 90 * kDeg, 500, 0.5 * kDeg);
  const qd::approximate::TargetFit a = qd::approximate::fit_targets(s.normals, s.areas);
  for (int k = 0; k < 50; ++k) {  // far-off zero-area samples, e.g. from degenerate faces
    s.normals.push_back(Vec3(0, std::cos(k), std::sin(k)).normalized());
    s.areas.push_back(0.0);
  }
  const qd::approximate::TargetFit b = qd::approximate::fit_targets(s.normals, s.areas);
  for (size_t i = 0; i < a.targets.size(); ++i) EXPECT_EQ(a.targets[i], b.targets[i]);
  EXPECT_DOUBLE_EQ(a.residual_deg, b.residual_deg);
}

TEST(TargetNormals, OrientationSignMatters) {
  // Flipping every normal gives the antipodal curve: targets flip too (normals are not lines).
  Samples s = cone(Vec3(0, 0, 1), 60 * kDeg, 0.0, 120 * kDeg, 800, 0.5 * kDeg);
  const qd::approximate::TargetFit a = qd::approximate::fit_targets(s.normals, s.areas);
  for (Vec3& n : s.normals) n = -n;
  const qd::approximate::TargetFit b = qd::approximate::fit_targets(s.normals, s.areas);
  for (size_t i = 0; i < s.normals.size(); ++i) {
    EXPECT_NEAR(angle(b.targets[i], Vec3(0, 0, 1)) / kDeg, 120.0, 0.6);
    EXPECT_LT(angle(-a.targets[i], b.targets[i]) / kDeg, 0.3);
  }
}

TEST(TargetNormals, BadInputThrows) {
  const std::vector<Vec3> n = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1),
                               Vec3(1, 1, 0).normalized()};
  EXPECT_THROW(qd::approximate::fit_targets(n, {1.0, 1.0, 0.0, 0.0}),
               qd::common::Error);  // 2 positive areas
  EXPECT_THROW(qd::approximate::fit_targets(n, {1.0, 1.0, 1.0}),
               qd::common::Error);  // size mismatch
  EXPECT_THROW(qd::approximate::fit_targets(n, {1.0, -1.0, 1.0, 1.0}), qd::common::Error);
  std::vector<Vec3> bad = n;
  bad[1] = Vec3(std::nan(""), 0, 0);
  EXPECT_THROW(qd::approximate::fit_targets(bad, {1.0, 1.0, 1.0, 1.0}), qd::common::Error);
  EXPECT_NO_THROW(
      qd::approximate::fit_targets(bad, {1.0, 0.0, 1.0, 1.0}));  // a zero-area NaN weighs nothing
}

TEST(TargetNormals, TimingFor1kAnd100kSamples) {
  auto phi = [](double t) { return kPi / 2 + 15 * kDeg * std::sin(3 * t); };
  for (int count : {1000, 100000}) {
    const Samples s = curve_samples(random_rotation(4), 0.0, 140 * kDeg, phi, count, 0.8 * kDeg);
    qd::approximate::fit_targets(s.normals, s.areas);  // warm-up
    const int reps = count <= 1000 ? 50 : 3;
    const auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < reps; ++r) qd::approximate::fit_targets(s.normals, s.areas);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() /
        reps;
    std::printf("fit_targets on %d samples: %.3f ms\n", count, ms);
    // Generous bounds (shared machine); the brief's targets are 2 ms and 100 ms.
    EXPECT_LT(ms, count <= 1000 ? 20.0 : 1000.0);
  }
}

TEST(TargetNormals, DegenerateInputsGiveUnitTargetsOrClearErrors) {
  const Vec3 a = Vec3(0.3, 0.4, 0.5).normalized(), b = Vec3(-0.5, 0.1, 0.7).normalized();
  std::vector<std::vector<Vec3>> cases = {
      {a, a, a},                         // the minimum: 3 identical normals
      {a, b, a},                         // 3 samples, two directions
      {a, a, a, a, b, b, b, b},          // a crease: two flat halves
      {a, a, a, -a, -a, -a},             // a sheet folded flat onto itself
      {a, b, a.cross(b).normalized()}};  // 3 orthogonal-ish directions
  for (size_t c = 0; c < cases.size(); ++c) {
    const std::vector<double> areas(cases[c].size(), 1.0);
    try {
      const qd::approximate::TargetFit fit = qd::approximate::fit_targets(cases[c], areas);
      expect_unit(fit.targets);
      EXPECT_TRUE(std::isfinite(fit.residual_deg)) << "case " << c;
    } catch (const qd::common::Error& e) {
      EXPECT_GT(std::string(e.what()).size(), 20u) << "case " << c;  // a sentence, not a crash
    }
  }
  // A crease: every target lies on the great-circle arc between the two normals.
  const std::vector<Vec3>& crease = cases[2];
  const qd::approximate::TargetFit fit =
      qd::approximate::fit_targets(crease, std::vector<double>(crease.size(), 1.0));
  const Vec3 axis = a.cross(b).normalized();
  for (const Vec3& t : fit.targets) EXPECT_LT(std::abs(t.dot(axis)), std::sin(1.0 * kDeg));
}
