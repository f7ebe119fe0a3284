#include "flatten/face_distortion.h"

#include <algorithm>
#include <cmath>

namespace qd::flatten {

Stretch stretch(const Eigen::Matrix2d& J) {
  const double e = 0.5 * (J(0, 0) + J(1, 1)), h = 0.5 * (J(1, 0) - J(0, 1));
  const double f = 0.5 * (J(0, 0) - J(1, 1)), g = 0.5 * (J(1, 0) + J(0, 1));
  const double q = std::hypot(e, h), r = std::hypot(f, g);
  return Stretch{q + r, std::abs(q - r), q <= r};
}

double length_distortion(const Stretch& s) { return std::max(s.s1 - 1, 1 - s.s2); }

double signed_stretch(const Stretch& s) {
  return s.s2 < 1 && 1 - s.s2 > s.s1 - 1 ? -(1 - s.s2) : s.s1 - 1;
}

}  // namespace qd::flatten
