// Cone proxy fit (D-Charts' proxy fitting step, with the candidate axes and apex angles
// described in cone_fit.h) and the fit error of a set of faces.
#include "segment/cone_fit.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace qd::segment {

namespace {

// The angles α_t = ∠(n_t, axis) of a set of faces: range and area-weighted moments, the latter
// of β = α − α_first so that a tight set does not cancel.
struct AngleStats {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  double shift = 0, area = 0, first = 0, second = 0;  // α_first, Σa, Σa·β, Σa·β²
  double largest = 0;                                 // max |α − θ| for a given θ

  AngleStats(const FaceGeometry& g, const std::vector<int>& faces, const Vec3& axis, double theta) {
    if (!faces.empty()) shift = angle_between(g.normal[faces.front()], axis);
    for (const int f : faces) {
      const double alpha = angle_between(g.normal[f], axis), a = g.area[f], beta = alpha - shift;
      lo = std::min(lo, alpha);
      hi = std::max(hi, alpha);
      largest = std::max(largest, std::abs(alpha - theta));
      area += a;
      first += a * beta;
      second += a * beta * beta;
    }
  }
  double mean() const { return shift + (area > 0 ? first / area : 0.0); }
  double rms_about(double theta) const {
    const double t = theta - shift;
    const double mean_square = area > 0 ? (second - 2 * t * first + t * t * area) / area : 0.0;
    return std::sqrt(std::max(0.0, mean_square));
  }
};

// The cone about `axis` with apex angle theta, seen from the end of the axis that makes
// theta ≤ π/2.
ConeFit cone(const Vec3& axis, double theta, double max_error, double rms_error) {
  ConeFit fit;
  fit.proxy = theta > M_PI / 2 ? ConeProxy{-axis, M_PI - theta} : ConeProxy{axis, theta};
  fit.max_error = max_error;
  fit.rms_error = rms_error;
  return fit;
}

}  // namespace

NormalMoments normal_moments(const FaceGeometry& g, const std::vector<int>& faces) {
  NormalMoments m;
  for (const int f : faces) m.add(g.normal[f], g.area[f]);
  return m;
}

ConeFit measure_cone(const FaceGeometry& g, const std::vector<int>& faces, const ConeProxy& c) {
  const AngleStats s(g, faces, c.axis, c.angle);
  return cone(c.axis, c.angle, s.largest, s.rms_about(c.angle));
}

bool better_fit(const ConeFit& a, const ConeFit& b, double limit) {
  const bool a_within = a.max_error <= limit, b_within = b.max_error <= limit;
  if (a_within != b_within) return a_within;
  if (!a_within) return a.rms_error < b.rms_error;
  if (std::abs(a.max_error - b.max_error) > kAxisTie) return a.max_error < b.max_error;
  return a.proxy.angle < b.proxy.angle - kAxisTie;
}

ConeFit fit_cone(const FaceGeometry& g, const std::vector<int>& faces, double limit,
                 const std::vector<Vec3>& extra_axes) {
  const NormalMoments m = normal_moments(g, faces);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(m.covariance());
  std::vector<Vec3> axes = extra_axes;
  for (int k = 0; k < 3; ++k) axes.push_back(eigen.eigenvectors().col(k));
  if (m.sum.norm() > 1e-12 * m.area) axes.push_back(m.sum.normalized());
  ConeFit best;
  bool first = true;
  for (const Vec3& axis : axes) {
    const AngleStats s(g, faces, axis, 0.0);
    const double midrange = 0.5 * (s.lo + s.hi), mean = s.mean();
    for (const ConeFit& fit :
         {cone(axis, midrange, 0.5 * (s.hi - s.lo), s.rms_about(midrange)),
          cone(axis, mean, std::max(mean - s.lo, s.hi - mean), s.rms_about(mean))})
      if (first || better_fit(fit, best, limit)) {
        best = fit;
        first = false;
      }
  }
  return best;
}

double max_error_lower_bound(const NormalMoments& m) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(m.covariance(),
                                                             Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(0.0, eigen.eigenvalues()(0)));
}

}  // namespace qd::segment
