// Colour ramp for per-vertex quality, shared by the quasidev command and both MeshLab plugins.
// Inputs: per-vertex quality values (e.g. Gaussian curvature K after the filter, or displacement).
// Outputs: a robust range [lo, hi] (percentiles, so a few extreme vertices do not wash out the
// ramp) and, for the command, an RGB colour per value on a red→yellow→green→cyan→blue ramp with
// red at lo and blue at hi (the same stops as vcg's Color4b::ColorRamp, so the command and the
// plugins colour alike).
#pragma once

#include <array>
#include <vector>

namespace qd::common {

struct QualityRange {
  double lo = 0;
  double hi = 0;
};

// Default percentiles of the robust range.
constexpr double kRampLowPercent = 2.0;
constexpr double kRampHighPercent = 98.0;

// The low_percent-th and high_percent-th percentiles (linear interpolation between order
// statistics) of the finite values; non-finite values are ignored. Empty input or no finite
// value gives {0, 0}. Requires 0 <= low_percent <= high_percent <= 100.
QualityRange robust_quality_range(const std::vector<double>& quality,
                                  double low_percent = kRampLowPercent,
                                  double high_percent = kRampHighPercent);

// A range symmetric about 0, [-m, m], with m the high_percent-th percentile of |q| over the finite
// values, but at least min_half_width (> 0): 0 is then the ramp's middle (green), and values
// smaller than min_half_width do not get the whole ramp.
QualityRange symmetric_quality_range(const std::vector<double>& quality, double min_half_width,
                                     double high_percent = kRampHighPercent);

// Colour of `value` on the ramp over `range`: red at lo, yellow, green at the middle, cyan, blue at
// hi; values outside the range are clamped; a degenerate range (lo == hi) gives green; a
// non-finite value gives grey.
std::array<unsigned char, 3> ramp_color(double value, const QualityRange& range);

}  // namespace qd::common
