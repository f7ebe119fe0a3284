// Digital image of the DEGI, modified Goshtasby field and skeleton pixels; see digital_image.h.
#include "approximate/digital_image.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <utility>

namespace qd::approximate {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Choice (the paper gives no grid size): a fixed modest grid keeps Step 1 fast and the field
// local. The samples' longer extent spans kInnerPixels; a tube spans 2π with kTubePixels.
constexpr int kInnerPixels = 144;
constexpr int kTubePixels = 240;
constexpr int kEffectRadius = 4;     // effect region of Eq. 11 (pixels)
constexpr double kBandPixels = 0.7;  // band thickness (φ standard deviation) in pixels, at most
constexpr int kMargin = kEffectRadius + 2;
// Ridge pixels need a field above this fraction of the maximum (ignores the faint rim).
constexpr double kRidgeFloor = 0.01;
// Largest slope along a ridge, relative to the curvature across it (pixels).
constexpr double kAlongSlope = 2.0;
// A pixel is blob-like when the curvature along the ridge is below this share of the one across.
constexpr double kBlobRatio = 0.5;

}  // namespace

Vec2 DigitalImage::to_pixel(const Vec2& tp) const {
  return Vec2((tp.x() - theta0) / pixel, (tp.y() - phi0) / pixel);
}

Vec2 DigitalImage::to_theta_phi(const Vec2& px) const {
  return Vec2(theta0 + px.x() * pixel, phi0 + px.y() * pixel);
}

namespace {

// θ inside [lo, hi] with a tolerance: the samples that bound the seam's gap sit exactly on
// lo and hi, and must count whatever the round-off.
bool within(double theta, double lo, double hi) {
  constexpr double kTolerance = 1e-9;
  return theta >= lo - kTolerance && theta <= hi + kTolerance;
}

// Number of cells of size `cell` that cover `length` (at least 1). The ratio is often a whole
// number up to round-off (cell = length / n): the tolerance keeps the count, and so the whole
// image, independent of round-off (rotation equivariance).
int whole_cells(double length, double cell) {
  return std::max(1, static_cast<int>(std::ceil(length / cell - 1e-9)));
}

// Weighted quantiles (share/2, 1 − share/2) of φ ∈ [0, π], exact (a data-driven bin edge
// would break rotation equivariance for noise-free normals lying on a bin edge): a histogram
// finds the bin that holds each quantile, then that bin's samples are sorted. Only samples
// with w > 0 and θ in [theta_lo, theta_hi] count.
Vec2 phi_range(const std::vector<Vec2>& tp, const std::vector<double>& w, double theta_lo,
               double theta_hi, double share) {
  constexpr int kBins = 1024;
  std::vector<double> hist(kBins, 0.0);
  std::vector<int> bin(tp.size(), -1);
  double total = 0;
  for (size_t i = 0; i < tp.size(); ++i) {
    if (w[i] <= 0 || !within(tp[i].x(), theta_lo, theta_hi)) continue;
    bin[i] = std::clamp(static_cast<int>(tp[i].y() / kPi * kBins), 0, kBins - 1);
    hist[bin[i]] += w[i];
    total += w[i];
  }
  if (!(total > 0)) return Vec2(0.0, kPi);
  const double target = 0.5 * share * total;
  auto quantile = [&](int step) {  // step +1: lower quantile, -1: upper quantile
    double acc = 0;
    int b = step > 0 ? 0 : kBins - 1;
    while (acc + hist[b] <= target && b + step >= 0 && b + step < kBins) acc += hist[b], b += step;
    std::vector<std::pair<double, double>> in_bin;
    for (size_t i = 0; i < tp.size(); ++i)
      if (bin[i] == b) in_bin.push_back({step * tp[i].y(), w[i]});
    std::sort(in_bin.begin(), in_bin.end());
    for (const auto& [signed_phi, weight] : in_bin)
      if ((acc += weight) > target) return step * signed_phi;
    return step * in_bin.back().first;
  };
  return Vec2(quantile(1), quantile(-1));
}

// Thickness of the point distribution across the curve: weighted median over θ-columns of
// width `column` of the weighted standard deviation of φ in the column.
double band_sigma(const std::vector<Vec2>& tp, const std::vector<double>& w, double theta_lo,
                  double theta_hi, double phi_lo, double column) {
  const int columns = whole_cells(theta_hi - theta_lo, column);
  std::vector<Eigen::Vector3d> acc(columns, Eigen::Vector3d::Zero());  // Σw, Σwφ, Σwφ²
  for (size_t i = 0; i < tp.size(); ++i) {
    if (w[i] <= 0 || !within(tp[i].x(), theta_lo, theta_hi)) continue;
    const double y = tp[i].y() - phi_lo;
    acc[std::clamp(static_cast<int>((tp[i].x() - theta_lo) / column), 0, columns - 1)] +=
        w[i] * Eigen::Vector3d(1.0, y, y * y);
  }
  std::vector<std::pair<double, double>> sigma_mass;
  double total = 0;
  for (const Eigen::Vector3d& a : acc)
    if (a.x() > 0) {
      const double mean = a.y() / a.x();
      sigma_mass.push_back({std::sqrt(std::max(a.z() / a.x() - mean * mean, 0.0)), a.x()});
      total += a.x();
    }
  std::sort(sigma_mass.begin(), sigma_mass.end());
  double acc_mass = 0;
  for (const auto& [sigma, mass] : sigma_mass)
    if ((acc_mass += mass) >= 0.5 * total) return sigma;
  return 0.0;
}

}  // namespace

DigitalImage rasterise(const std::vector<Vec2>& theta_phi, const std::vector<double>& w,
                       bool periodic, double theta_gap, double outlier_share) {
  const double theta_lo = periodic ? 0.0 : 0.5 * theta_gap;
  const double theta_hi = periodic ? 2 * kPi : 2 * kPi - 0.5 * theta_gap;
  const Vec2 phi = phi_range(theta_phi, w, theta_lo, theta_hi, outlier_share);
  const Vec2 extent(theta_hi - theta_lo, phi.y() - phi.x());
  DigitalImage im;
  im.periodic = periodic;
  im.effect_radius = kEffectRadius;
  // Pixel size: the samples' longer extent over kInnerPixels (a tube: 2π over kTubePixels),
  // but at least the band thickness over kBandPixels, so that noise across the curve is
  // smoothed by the effect region instead of breaking the ridge into parallel pieces.
  const double fine =
      periodic ? 2 * kPi / kTubePixels : std::max({extent.x(), extent.y(), 1e-9}) / kInnerPixels;
  im.pixel =
      std::max(fine, band_sigma(theta_phi, w, theta_lo, theta_hi, phi.x(), fine) / kBandPixels);
  if (periodic) {
    im.width = whole_cells(2 * kPi, im.pixel);
    im.pixel = 2 * kPi / im.width;
    im.theta0 = 0;
  } else {
    im.width = whole_cells(extent.x(), im.pixel) + 2 * kMargin + 1;
    im.theta0 = theta_lo - (kMargin + 0.5) * im.pixel;
  }
  // The extreme samples sit on pixel centres (the extra half pixel): noise-free normals then
  // give a ridge on pixel centres, not halfway between two rows where its detection would
  // hinge on round-off.
  im.height = whole_cells(extent.y(), im.pixel) + 2 * kMargin + 1;
  im.phi0 = phi.x() - (kMargin + 0.5) * im.pixel;

  // Eq. 12: r(p) = k·|SP|·Σ_{SP} w with k chosen so that max r = 1 (k only scales the field).
  // Choice: a sample counts in its 4 nearest pixels with bilinear shares (|SP| and Σw become
  // fractional), so the field keeps the samples' sub-pixel positions; whole-pixel binning
  // biased coarse Gauss images (identical normals) by up to half a pixel.
  const size_t pixels = static_cast<size_t>(im.width) * im.height;
  std::vector<double> count(pixels, 0.0), weight(pixels, 0.0);
  for (size_t i = 0; i < theta_phi.size(); ++i) {
    if (w[i] <= 0) continue;
    const Vec2 p = im.to_pixel(theta_phi[i]) - Vec2(0.5, 0.5);  // relative to pixel centres
    const int x0 = static_cast<int>(std::floor(p.x())), y0 = static_cast<int>(std::floor(p.y()));
    if ((!periodic && (x0 < -1 || x0 >= im.width)) || y0 < -1 || y0 >= im.height)
      continue;  // stray outlier outside the image
    const double fx = p.x() - x0, fy = p.y() - y0;
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        int x = x0 + dx;
        const int y = y0 + dy;
        if (periodic) x = ((x % im.width) + im.width) % im.width;
        if (x < 0 || x >= im.width || y < 0 || y >= im.height) continue;
        const double share = (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy);
        count[static_cast<size_t>(y) * im.width + x] += share;
        weight[static_cast<size_t>(y) * im.width + x] += share * w[i];
      }
  }
  im.r.assign(pixels, 0.0);
  double rmax = 0;
  for (size_t k = 0; k < pixels; ++k) {
    im.r[k] = count[k] * weight[k];
    rmax = std::max(rmax, im.r[k]);
  }
  if (rmax > 0)
    for (double& r : im.r) r /= rmax;
  return im;
}

void goshtasby_field(DigitalImage& im) {
  // Eqs. 10–11 with our reading:
  //  * sign(‖p − p_i‖) as printed (1 when the distance EXCEEDS the threshold) would keep the far
  //    field and drop the near one; we read it inverted: pixel p_i acts on p only inside its
  //    effect region ‖p − p_i‖ <= ρ (ρ = effect_radius). This makes the field local and cheap.
  //  * Eq. 10's Σ sqrt(d² + r²) is a sum of convex functions (one minimum, no ridges). We use
  //    the multiquadric turned into a bump that vanishes at the cut-off,
  //        f(p) = Σ_{‖p−p_i‖<=ρ} r(p_i) · (sqrt(ρ² + s²) − sqrt(‖p − p_i‖² + s²)) / (sqrt(ρ² + s²)
  //        − s),
  //    with the smoothing constant s = 1 pixel in the root (Goshtasby's constant r) and the
  //    pixel weight r(p_i) of Eq. 12 as amplitude, so more and larger faces pull the ridge.
  const int rho = im.effect_radius;
  const double s = 1.0, top = std::sqrt(rho * rho + s * s);
  const int side = 2 * rho + 1;
  std::vector<double> kernel(static_cast<size_t>(side) * side, 0.0);
  for (int dy = -rho; dy <= rho; ++dy)
    for (int dx = -rho; dx <= rho; ++dx) {
      const double d2 = dx * dx + dy * dy;
      if (d2 <= rho * rho)
        kernel[static_cast<size_t>(dy + rho) * side + (dx + rho)] =
            (top - std::sqrt(d2 + s * s)) / (top - s);
    }
  im.field.assign(im.r.size(), 0.0);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const double r = im.r[static_cast<size_t>(y) * im.width + x];
      if (r == 0) continue;
      for (int dy = -rho; dy <= rho; ++dy) {
        const int yy = y + dy;
        if (yy < 0 || yy >= im.height) continue;
        for (int dx = -rho; dx <= rho; ++dx) {
          int xx = x + dx;
          if (im.periodic)
            xx = (xx + im.width) % im.width;
          else if (xx < 0 || xx >= im.width)
            continue;
          im.field[static_cast<size_t>(yy) * im.width + xx] +=
              r * kernel[static_cast<size_t>(dy + rho) * side + (dx + rho)];
        }
      }
    }
}

std::vector<SkeletonPoint> skeleton_pixels(const DigitalImage& im) {
  const double fmax = *std::max_element(im.field.begin(), im.field.end());
  auto f = [&](int x, int y) {
    if (im.periodic) x = (x + im.width) % im.width;
    return im.field[static_cast<size_t>(y) * im.width + x];
  };
  std::vector<SkeletonPoint> out;
  const int x_lo = im.periodic ? 0 : 1, x_hi = im.periodic ? im.width : im.width - 1;
  for (int y = 1; y + 1 < im.height; ++y)
    for (int x = x_lo; x < x_hi; ++x) {
      const double v = f(x, y);
      if (v <= kRidgeFloor * fmax) continue;
      // Central differences: gradient g and Hessian [a b; b c].
      const Vec2 g(0.5 * (f(x + 1, y) - f(x - 1, y)), 0.5 * (f(x, y + 1) - f(x, y - 1)));
      const double a = f(x + 1, y) - 2 * v + f(x - 1, y);
      const double c = f(x, y + 1) - 2 * v + f(x, y - 1);
      const double b =
          0.25 * (f(x + 1, y + 1) - f(x + 1, y - 1) - f(x - 1, y + 1) + f(x - 1, y - 1));
      const double mean = 0.5 * (a + c), dev = std::sqrt(0.25 * (a - c) * (a - c) + b * b);
      const double lambda = mean - dev;  // most negative curvature: across the ridge
      if (!(lambda < 0)) continue;
      Vec2 across = std::abs(lambda - c) + std::abs(b) > std::abs(lambda - a) + std::abs(b)
                        ? Vec2(lambda - c, b)
                        : Vec2(b, lambda - a);
      if (across.squaredNorm() == 0) across = a <= c ? Vec2(1, 0) : Vec2(0, 1);
      across.normalize();
      // Local maximum across the ridge: the 1-D Newton step to the maximum stays in the pixel.
      const Vec2 offset = across * (-g.dot(across) / lambda);
      if (std::abs(offset.x()) > 0.5 || std::abs(offset.y()) > 0.5) continue;
      // A ridge runs nearly level: the slope along it must be small against the curvature
      // across it. This rejects the flanks of blobs and of a band's end cap, where every point
      // is a maximum along its own contour line. Where the field is a blob (curved downwards
      // along as well: a cluster of identical normals), only its peak counts: the Newton step
      // along must stay in the pixel too.
      const Vec2 along(-across.y(), across.x());
      const double mu = mean + dev;  // curvature along the ridge
      if (mu < kBlobRatio * lambda ? std::abs(g.dot(along) / mu) > 0.5
                                   : std::abs(g.dot(along)) > kAlongSlope * -lambda)
        continue;
      out.push_back({Vec2(x + 0.5, y + 0.5) + offset, x, y, v});
    }
  return out;
}

}  // namespace qd::approximate
