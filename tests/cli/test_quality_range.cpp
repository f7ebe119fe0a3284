// Robust quality range and colour ramp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/quality_range.h"
#include "flatten/stretch_ramp.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

TEST(QualityRange, PercentilesIgnoreOutliersAndNonFiniteValues) {
  std::vector<double> q;
  for (int i = 0; i <= 100; ++i) q.push_back(i);
  q.push_back(std::numeric_limits<double>::quiet_NaN());
  q.push_back(std::numeric_limits<double>::infinity());
  const qd::common::QualityRange r = qd::common::robust_quality_range(q);
  EXPECT_DOUBLE_EQ(r.lo, 2.0);
  EXPECT_DOUBLE_EQ(r.hi, 98.0);
  q.push_back(1e9);  // one outlier barely shifts the range
  EXPECT_LT(qd::common::robust_quality_range(q).hi, 100.0);
  const qd::common::QualityRange full = qd::common::robust_quality_range({3, 1, 2}, 0, 100);
  EXPECT_EQ(full.lo, 1.0);
  EXPECT_EQ(full.hi, 3.0);
  EXPECT_DOUBLE_EQ(qd::common::robust_quality_range({0, 10}, 25, 50).lo, 2.5);
  EXPECT_EQ(qd::common::robust_quality_range({}).hi, 0.0);
}

TEST(QualityRange, RampGoesRedGreenBlueAndClamps) {
  const qd::common::QualityRange r{-1, 1};
  using C = std::array<unsigned char, 3>;
  EXPECT_EQ(qd::common::ramp_color(-1, r), (C{255, 0, 0}));
  EXPECT_EQ(qd::common::ramp_color(-5, r), (C{255, 0, 0}));
  EXPECT_EQ(qd::common::ramp_color(0, r), (C{0, 255, 0}));
  EXPECT_EQ(qd::common::ramp_color(1, r), (C{0, 0, 255}));
  EXPECT_EQ(qd::common::ramp_color(7, r), (C{0, 0, 255}));
  EXPECT_EQ(qd::common::ramp_color(-0.5, r), (C{255, 255, 0}));
  EXPECT_EQ(qd::common::ramp_color(0.5, r), (C{0, 255, 255}));
  EXPECT_EQ(qd::common::ramp_color(3, qd::common::QualityRange{2, 2}), (C{0, 255, 0}));
  // Monotone: red falls then blue rises along the ramp.
  int previous_red = 256, previous_blue = -1;
  for (int i = 0; i <= 40; ++i) {
    const C c = qd::common::ramp_color(-1 + i / 20.0, r);
    EXPECT_LE(c[0], previous_red);
    EXPECT_GE(c[2], previous_blue);
    previous_red = c[0];
    previous_blue = c[2];
  }
}

TEST(QualityRange, SymmetricRangeCentresZeroWithAFloor) {
  std::vector<double> q;
  for (int i = 0; i <= 100; ++i) q.push_back(i - 70.0);  // |q| up to 70, 98th percentile 68
  q.push_back(std::numeric_limits<double>::quiet_NaN());
  const qd::common::QualityRange r = qd::common::symmetric_quality_range(q, 1.0);
  EXPECT_DOUBLE_EQ(r.hi, 68.0);
  EXPECT_DOUBLE_EQ(r.lo, -68.0);
  EXPECT_EQ(qd::common::symmetric_quality_range({1e-9, -2e-9}, 0.5).hi, 0.5);
  EXPECT_EQ(qd::common::symmetric_quality_range({}, 0.5).lo, -0.5);
  // The stretch ramp: exact developments (round-off only) read green; ±0.1 % at its ends.
  const qd::common::QualityRange stretch = qd::flatten::stretch_ramp_range({1e-12, -3e-12, 0});
  EXPECT_EQ(qd::common::ramp_color(-3e-12, stretch), (std::array<unsigned char, 3>{0, 255, 0}));
  EXPECT_EQ(stretch.hi, qd::flatten::kStretchRampFloor);
}

}  // namespace
