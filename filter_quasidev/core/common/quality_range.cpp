#include "common/quality_range.h"

#include <algorithm>
#include <cmath>

namespace qd::common {

namespace {

// Percentile p (0..100) of sorted finite values, linear between neighbouring order statistics.
double percentile_of_sorted(const std::vector<double>& sorted, double p) {
  const double pos = p / 100.0 * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(pos));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double t = pos - static_cast<double>(below);
  return sorted[below] + t * (sorted[above] - sorted[below]);
}

unsigned char to_byte(double unit) {
  return static_cast<unsigned char>(std::lround(std::clamp(unit, 0.0, 1.0) * 255.0));
}

}  // namespace

QualityRange robust_quality_range(const std::vector<double>& quality, double low_percent,
                                  double high_percent) {
  std::vector<double> finite;
  finite.reserve(quality.size());
  for (double q : quality)
    if (std::isfinite(q)) finite.push_back(q);
  if (finite.empty()) return {};
  std::sort(finite.begin(), finite.end());
  return {percentile_of_sorted(finite, low_percent), percentile_of_sorted(finite, high_percent)};
}

QualityRange symmetric_quality_range(const std::vector<double>& quality, double min_half_width,
                                     double high_percent) {
  std::vector<double> magnitude;
  magnitude.reserve(quality.size());
  for (double q : quality)
    if (std::isfinite(q)) magnitude.push_back(std::fabs(q));
  double m = min_half_width;
  if (!magnitude.empty()) {
    std::sort(magnitude.begin(), magnitude.end());
    m = std::max(m, percentile_of_sorted(magnitude, high_percent));
  }
  return {-m, m};
}

std::array<unsigned char, 3> ramp_color(double value, const QualityRange& range) {
  if (!std::isfinite(value)) return {128, 128, 128};
  const double span = range.hi - range.lo;
  const double t = span > 0 ? std::clamp((value - range.lo) / span, 0.0, 1.0) : 0.5;
  // Four equal legs: red→yellow, yellow→green, green→cyan, cyan→blue.
  const double s = t * 4.0;
  if (s < 1) return {255, to_byte(s), 0};
  if (s < 2) return {to_byte(2 - s), 255, 0};
  if (s < 3) return {0, 255, to_byte(s - 2)};
  return {0, to_byte(4 - s), 255};
}

}  // namespace qd::common
