// DEGI moments, shape tests and the rotation R of Eq. 9; see gauss_image.h.
#include "approximate/gauss_image.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

#include "approximate/common_names.h"
#include "common/error.h"

namespace qd::approximate {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// Smallest-eigenvalue eigenvector of a symmetric 3x3 matrix.
Vec3 smallest_eigenvector(const Eigen::Matrix3d& S) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(S);
  return es.eigenvectors().col(0);
}

// The pole's sign is chosen from the data, never from the axes: the first odd moment
// Σ a (n·p)^k (k = 1, else 3) that is not negligible must be >= 0.
Vec3 with_data_sign(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                    const GaussMoments& m, const Vec3& p) {
  double first = 0, third = 0;
  for (size_t i = 0; i < normals.size(); ++i) {
    const double x = normals[i].dot(p);
    first += areas[i] * x;
    third += areas[i] * x * x * x;
  }
  const double moment = std::abs(first) > 1e-12 * m.total_area ? first : third;
  return moment >= 0 ? p : Vec3(-p);
}

// Sorts (θ, area) pairs, θ ∈ [−π, π], by θ: a bucket pass (one bucket per pair on average)
// then insertion sort inside the buckets; linear time for the spread-out angles of a DEGI.
void sort_by_angle(std::vector<std::pair<double, double>>& ta) {
  const size_t n = ta.size();
  std::vector<size_t> start(n + 1, 0);
  auto bucket = [&](double theta) {
    return std::min(static_cast<size_t>((theta + kPi) / (2 * kPi) * static_cast<double>(n)), n - 1);
  };
  for (const auto& p : ta) ++start[bucket(p.first) + 1];
  for (size_t b = 0; b < n; ++b) start[b + 1] += start[b];
  std::vector<std::pair<double, double>> sorted(n);
  std::vector<size_t> fill(start.begin(), start.end() - 1);
  for (const auto& p : ta) sorted[fill[bucket(p.first)]++] = p;
  for (size_t b = 0; b < n; ++b)
    std::sort(sorted.begin() + static_cast<std::ptrdiff_t>(start[b]),
              sorted.begin() + static_cast<std::ptrdiff_t>(start[b + 1]));
  ta.swap(sorted);
}

}  // namespace

GaussMoments gauss_moments(const std::vector<Vec3>& normals, const std::vector<double>& areas) {
  if (normals.size() != areas.size())
    throw Error("internal: " + std::to_string(normals.size()) + " normals but " +
                std::to_string(areas.size()) + " areas were given to the Gauss-image fit");
  GaussMoments m;
  int positive = 0;
  for (size_t i = 0; i < normals.size(); ++i) {
    const double a = areas[i];
    if (!std::isfinite(a) || a < 0)
      throw Error("face " + std::to_string(i) + " of the patch has an invalid area (" +
                  std::to_string(a) + "); repair the mesh (remove degenerate/NaN faces)");
    if (a == 0) continue;  // zero-area samples weigh 0 (docs/design.md Step 1.1)
    const Vec3& n = normals[i];
    if (!n.allFinite() || std::abs(n.norm() - 1.0) > 1e-6)
      throw Error("face " + std::to_string(i) +
                  " of the patch has no valid unit normal; "
                  "repair the mesh (remove degenerate/NaN faces)");
    ++positive;
    m.total_area += a;
    m.resultant += a * n;
    m.scatter += a * n * n.transpose();
  }
  if (positive < 3)
    throw Error("a patch has only " + std::to_string(positive) +
                " faces with positive area; at least 3 are needed to fit target normals: "
                "merge it with a neighbouring patch");
  return m;
}

bool fills_sphere(const GaussMoments& m) {
  const double resultant = m.resultant.norm() / m.total_area;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(m.scatter / m.total_area,
                                                          Eigen::EigenvaluesOnly);
  return resultant < 0.1 && es.eigenvalues()(0) > 0.2;
}

bool is_point_like(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                   const GaussMoments& m) {
  // Choice (docs/design.md Step 1.3, "Planar Gauss images"): the Gauss image is a point when the
  // area-weighted angular spread about the mean normal is below 1° in every direction, or is
  // an isotropic blob (minor/major variance > 0.3, i.e. noise rather than a curve) below 6°.
  constexpr double kPointSpread = 1.0 * kDeg, kBlobSpread = 6.0 * kDeg, kIsotropy = 0.3;
  if (m.resultant.norm() < 0.5 * m.total_area) return false;
  const Vec3 mean = m.resultant.normalized();
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();  // covariance of the log map at the mean
  for (size_t i = 0; i < normals.size(); ++i) {
    if (areas[i] == 0) continue;
    const Vec3 t = normals[i] - normals[i].dot(mean) * mean;
    const double s = t.norm();
    if (s == 0) continue;
    const Vec3 d = t * (std::atan2(s, normals[i].dot(mean)) / s);
    C += areas[i] * d * d.transpose();
  }
  C /= m.total_area;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C, Eigen::EigenvaluesOnly);
  const double major = std::max(es.eigenvalues()(2), 0.0),
               minor = std::max(es.eigenvalues()(1), 0.0);
  const double spread = std::sqrt(major);
  return spread < kPointSpread || (spread < kBlobSpread && minor > kIsotropy * major);
}

Vec3 best_great_circle_pole(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                            const GaussMoments& m) {
  // Start: smallest-eigenvalue eigenvector of Σ a n nᵀ (least-squares great circle). Then a
  // fixed number of iteratively reweighted steps for Σ a |asin(n·p)| (Eq. 9): the weight of a
  // sample is ρ'(x)/x with ρ(x) = asin|x|, i.e. a / (|x| sqrt(1 − x²)), |x| floored at
  // sin(0.5°) so samples on the circle stay finite. A fixed count keeps the result a smooth,
  // deterministic function of the data (rotation-equivariant to round-off).
  constexpr int kIterations = 10;
  const double floor_x = std::sin(0.5 * kDeg);
  Vec3 p = smallest_eigenvector(m.scatter);
  for (int it = 0; it < kIterations; ++it) {
    double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;  // the 6 entries of Σ w n nᵀ
    for (size_t i = 0; i < normals.size(); ++i) {
      if (areas[i] == 0) continue;
      const Vec3& n = normals[i];
      const double x = std::min(std::max(std::abs(n.dot(p)), floor_x), 1.0 - 1e-12);
      const double w = areas[i] / (x * std::sqrt(1.0 - x * x));
      const double wx = w * n.x(), wy = w * n.y();
      xx += wx * n.x(), xy += wx * n.y(), xz += wx * n.z();
      yy += wy * n.y(), yz += wy * n.z(), zz += w * n.z() * n.z();
    }
    Eigen::Matrix3d S;
    S << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    const Vec3 q = smallest_eigenvector(S);
    p = q.dot(p) >= 0 ? q : Vec3(-q);
  }
  return with_data_sign(normals, areas, m, p);
}

Vec3 best_small_circle_pole(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                            const GaussMoments& m, double& misfit) {
  const Vec3 mean = m.resultant / m.total_area;
  const Eigen::Matrix3d covariance = m.scatter / m.total_area - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(covariance);
  misfit = std::max(es.eigenvalues()(0), 0.0);
  return with_data_sign(normals, areas, m, es.eigenvectors().col(0));
}

double great_circle_misfit(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                           const GaussMoments& m, const Vec3& pole) {
  double sum = 0;
  for (size_t i = 0; i < normals.size(); ++i)
    sum += areas[i] * normals[i].dot(pole) * normals[i].dot(pole);
  return sum / m.total_area;
}

GaussFrame gauss_frame(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                       const Vec3& pole) {
  // Any orthonormal (e1, e2) first; the seam rotation below makes the final frame depend on
  // the data only.
  const Vec3 e1 = pole.unitOrthogonal();
  const Vec3 e2 = pole.cross(e1);
  std::vector<std::pair<double, double>> ta;  // (θ, area) of the positive-area samples
  ta.reserve(normals.size());
  double total = 0;
  for (size_t i = 0; i < normals.size(); ++i)
    if (areas[i] > 0) {
      ta.push_back({std::atan2(normals[i].dot(e2), normals[i].dot(e1)), areas[i]});
      total += areas[i];
    }
  sort_by_angle(ta);
  // Circular sweep over the sorted θ (doubled with +2π): for each sample i the farthest j such
  // that the samples strictly between them hold at most kGapOutlierShare of the area. The
  // widest such (i, j) is the robust empty gap; it depends on θ differences only.
  const size_t n = ta.size();
  auto theta = [&](size_t k) { return ta[k % n].first + (k >= n ? 2 * kPi : 0.0); };
  std::vector<double> prefix(2 * n + 1, 0.0);  // prefix[k] = area of doubled samples < k
  for (size_t k = 0; k < 2 * n; ++k) prefix[k + 1] = prefix[k] + ta[k % n].second;
  const double allowed = kGapOutlierShare * total;
  double widest = -1, centre = 0;
  size_t gap_i = 0, gap_j = 1;
  for (size_t i = 0, j = 1; i < n; ++i) {
    j = std::max(j, i + 1);
    while (j + 1 <= i + n && prefix[j + 1] - prefix[i + 1] <= allowed) ++j;
    const double span = theta(j) - theta(i);
    if (span > widest) widest = span, centre = theta(i) + 0.5 * span, gap_i = i, gap_j = j;
  }
  // Widest plain gap between neighbours outside the robust gap.
  double second = 0;
  for (size_t k = gap_j; k < gap_i + n; ++k) second = std::max(second, theta(k + 1) - theta(k));
  GaussFrame frame;
  const Vec3 f1 = std::cos(centre) * e1 + std::sin(centre) * e2;
  frame.R.row(0) = f1.transpose();
  frame.R.row(1) = pole.cross(f1).transpose();
  frame.R.row(2) = pole.transpose();
  frame.gap = widest;
  // Choice: the samples "cover all θ" (a tube, closed curve) when no gap stands out: the widest
  // is below 20°, or below 1.5x the widest other gap (a coarse tube whose faces give evenly
  // spaced normals).
  frame.closed = widest < 20.0 * kDeg || widest < 1.5 * second;
  return frame;
}

bool clear_of_poles(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                    const Vec3& pole, double clearance) {
  const double limit = std::cos(clearance);
  double near = 0, total = 0;
  for (size_t i = 0; i < normals.size(); ++i) {
    total += areas[i];
    if (std::abs(normals[i].dot(pole)) > limit) near += areas[i];
  }
  return near <= kGapOutlierShare * total;
}

Vec2 theta_phi(const Vec3& m) {
  // Eq. 9 (atan2 is the printed acos form, well conditioned everywhere), θ in [0, 2π).
  double theta = std::atan2(m.y(), m.x());
  if (theta < 0) theta += 2 * kPi;
  return Vec2(theta, std::acos(std::clamp(m.z(), -1.0, 1.0)));
}

Vec3 sphere_point(double theta, double phi) {
  const double s = std::sin(phi);
  return Vec3(s * std::cos(theta), s * std::sin(theta), std::cos(phi));
}

}  // namespace qd::approximate
