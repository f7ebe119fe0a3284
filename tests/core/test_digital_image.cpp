// Digital image, modified Goshtasby field and skeleton pixels (digital_image.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "approximate/digital_image.h"

using qd::approximate::Vec2;

namespace {

using namespace qd::approximate;

constexpr double kPi = 3.14159265358979323846;

// Samples along φ = phi0 + amp·sin(θ) for θ in [a, b], with φ noise.
void band(double a, double b, double phi0, double amp, double noise, int count,
          std::vector<Vec2>& tp, std::vector<double>& w, unsigned seed = 3) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(a, b);
  std::normal_distribution<double> g(0.0, noise);
  for (int i = 0; i < count; ++i) {
    const double t = u(rng);
    tp.push_back(Vec2(t, phi0 + amp * std::sin(t) + g(rng)));
    w.push_back(1.0);
  }
}

double field_at(const qd::approximate::DigitalImage& im, int x, int y) {
  return im.field[static_cast<size_t>(y) * im.width + x];
}

}  // namespace

// Σ sqrt(r) over the 2x2 pixels a sample at `tp` shares its weight with.
double root_weight_near(const qd::approximate::DigitalImage& im, const Vec2& tp) {
  const Vec2 p = im.to_pixel(tp) - Vec2(0.5, 0.5);
  const int x0 = static_cast<int>(std::floor(p.x())), y0 = static_cast<int>(std::floor(p.y()));
  double sum = 0;
  for (int y = y0; y <= y0 + 1; ++y)
    for (int x = x0; x <= x0 + 1; ++x)
      sum += std::sqrt(im.r[static_cast<size_t>(y) * im.width + x]);
  return sum;
}

TEST(DigitalImage, PixelWeightIsCountTimesArea) {
  // Eq. 12 with bilinear shares s: n samples of area w at one spot give r = n² s² w, so
  // Σ sqrt(r) over the spot's pixels is n·sqrt(w) (up to the common scale k).
  const Vec2 a(kPi - 0.7, 1.1), b(kPi + 0.31, 1.37), c(kPi, 1.2);
  const std::vector<Vec2> tp = {a, a, b, c, Vec2(kPi - 1, 1.0), Vec2(kPi + 1, 1.5)};
  const std::vector<double> w = {1.0, 1.0, 1.0, 0.0, 0.01, 0.01};  // c: zero area
  const qd::approximate::DigitalImage im =
      qd::approximate::rasterise(tp, w, false, 2 * kPi - 2.0, 0.0);
  EXPECT_NEAR(root_weight_near(im, a) / root_weight_near(im, b), 2.0, 1e-9);
  EXPECT_EQ(root_weight_near(im, c), 0.0);
  EXPECT_NEAR(*std::max_element(im.r.begin(), im.r.end()), 1.0, 1e-12);  // k normalises
}

TEST(DigitalImage, FieldIsLocalToTheEffectRegion) {
  std::vector<Vec2> tp;
  std::vector<double> w;
  band(kPi - 0.75, kPi + 0.75, 1.5, 0.0, 0.0, 200, tp, w);
  qd::approximate::DigitalImage im = qd::approximate::rasterise(tp, w, false, 2 * kPi - 1.5, 0.0);
  qd::approximate::goshtasby_field(im);
  const double rho = im.effect_radius;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      // Distance (pixels) from this pixel centre to the nearest occupied pixel centre.
      double nearest = 1e9;
      for (int yy = 0; yy < im.height; ++yy)
        for (int xx = 0; xx < im.width; ++xx)
          if (im.r[static_cast<size_t>(yy) * im.width + xx] > 0)
            nearest = std::min(nearest, std::hypot(x - xx, y - yy));
      if (nearest > rho) {
        EXPECT_EQ(field_at(im, x, y), 0.0);
      } else if (nearest < rho - 1) {
        EXPECT_GT(field_at(im, x, y), 0.0);
      }
    }
}

TEST(DigitalImage, SkeletonOfNoisyBandLiesOnItsCentreLine) {
  std::vector<Vec2> tp;
  std::vector<double> w;
  band(kPi - 1, kPi + 1, 1.6, 0.2, 0.01, 4000, tp, w);
  qd::approximate::DigitalImage im = qd::approximate::rasterise(tp, w, false, 2 * kPi - 2.0, 0.01);
  qd::approximate::goshtasby_field(im);
  const std::vector<qd::approximate::SkeletonPoint> sk = qd::approximate::skeleton_pixels(im);
  ASSERT_GT(sk.size(), 50u);
  int inside = 0;
  for (const qd::approximate::SkeletonPoint& p : sk) {
    const Vec2 tp_p = im.to_theta_phi(p.pos);
    if (std::abs(tp_p.x() - kPi) > 0.9) continue;  // away from the band's ends
    ++inside;
    EXPECT_NEAR(tp_p.y(), 1.6 + 0.2 * std::sin(tp_p.x()), 0.5 * im.pixel) << tp_p.x();
  }
  EXPECT_GT(inside, 40);
}

TEST(DigitalImage, PeriodicImageWrapsAcrossTheSeam) {
  std::vector<Vec2> tp;
  std::vector<double> w;
  for (int k = 0; k < 3000; ++k) {  // evenly spaced around θ
    tp.push_back(Vec2(2 * kPi * (k + 0.5) / 3000, 1.5));
    w.push_back(1.0);
  }
  qd::approximate::DigitalImage im = qd::approximate::rasterise(tp, w, true, 0.0, 0.0);
  qd::approximate::goshtasby_field(im);
  // The field along the band's row is as strong at the seam columns as in the middle.
  int row = 0;
  for (int y = 0; y < im.height; ++y)
    if (field_at(im, im.width / 2, y) > field_at(im, im.width / 2, row)) row = y;
  EXPECT_NEAR(field_at(im, 0, row) / field_at(im, im.width / 2, row), 1.0, 0.02);
  EXPECT_NEAR(field_at(im, im.width - 1, row) / field_at(im, im.width / 2, row), 1.0, 0.02);
  const std::vector<qd::approximate::SkeletonPoint> sk = qd::approximate::skeleton_pixels(im);
  std::vector<int> columns;
  for (const qd::approximate::SkeletonPoint& p : sk) columns.push_back(p.x);
  EXPECT_NE(std::find(columns.begin(), columns.end(), 0), columns.end());
  EXPECT_NE(std::find(columns.begin(), columns.end(), im.width - 1), columns.end());
}

TEST(DigitalImage, StrayOutliersStayOutOfTheImage) {
  std::vector<Vec2> tp;
  std::vector<double> w;
  band(kPi - 0.5, kPi + 0.5, 1.5, 0.0, 0.002, 1000, tp, w);
  const qd::approximate::DigitalImage clean =
      qd::approximate::rasterise(tp, w, false, 2 * kPi - 1.0, 0.01);
  tp.push_back(Vec2(kPi, 0.2));  // far off in φ, tiny share of the area
  w.push_back(1.0);
  const qd::approximate::DigitalImage with =
      qd::approximate::rasterise(tp, w, false, 2 * kPi - 1.0, 0.01);
  EXPECT_EQ(clean.height, with.height);
  EXPECT_DOUBLE_EQ(clean.pixel, with.pixel);
}
