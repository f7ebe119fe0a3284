// The digital image of the mapped DEGI (§5.1, Eqs. 10–12): rasterised (θ, φ) samples, the
// per-pixel weight r(p), the modified Goshtasby field and its skeleton (ridge) pixels.
//   rasterise:        (θ, φ) samples + weights -> image with r(p) (Eq. 12)
//   goshtasby_field:  image -> field f on every pixel (Eqs. 10–11, effect-region cut-off)
//   skeleton_pixels:  image -> sub-pixel ridge points of f
#pragma once

#include <vector>

#include "approximate/bspline.h"

namespace qd::approximate {

struct DigitalImage {
  int width = 0, height = 0;    // pixels along θ (x) and φ (y)
  double theta0 = 0, phi0 = 0;  // (θ, φ) of the image corner (x = y = 0)
  double pixel = 0;             // pixel size in radians (square pixels)
  bool periodic = false;        // x wraps: width·pixel = 2π (tube)
  int effect_radius = 0;        // effect-region radius of Eq. 11, in pixels
  std::vector<double> r;        // Eq. 12 weight per pixel, index y·width + x
  std::vector<double> field;    // Eq. 11 field per pixel

  Vec2 to_pixel(const Vec2& theta_phi) const;  // continuous pixel coordinates
  Vec2 to_theta_phi(const Vec2& px) const;
};

// Rasterises the samples (θ, φ) with weights w (face areas; w = 0 is skipped). Periodic images
// span θ ∈ [0, 2π); open ones θ ∈ [theta_gap/2, 2π − theta_gap/2] (the samples outside the
// seam's empty gap). In φ the image spans the weighted quantiles outlier_share/2 and
// 1 − outlier_share/2. Both get a margin; samples outside the image are stray outliers and
// are left out.
DigitalImage rasterise(const std::vector<Vec2>& theta_phi, const std::vector<double>& w,
                       bool periodic, double theta_gap, double outlier_share);

// Fills image.field (Eq. 11 with the choices documented at the definition).
void goshtasby_field(DigitalImage& image);

// A ridge point of the field: sub-pixel position (pixel units), its pixel and field value.
struct SkeletonPoint {
  Vec2 pos;
  int x = 0, y = 0;
  double strength = 0;
};

// Pixels where the field is a local maximum across the ridge (along the Hessian eigenvector of
// the most negative eigenvalue), with the sub-pixel ridge position.
std::vector<SkeletonPoint> skeleton_pixels(const DigitalImage& image);

}  // namespace qd::approximate
