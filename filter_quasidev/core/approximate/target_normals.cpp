// Step 1 of the paper (§5.1): DEGI -> rotation R (Eq. 9) -> digital image and skeleton
// (Eqs. 10–12) -> B-spline c_2D -> spherical curve c_3D = R⁻¹ S(c_2D) -> target normals.
#include "approximate/target_normals.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <nanoflann.hpp>
#include <string>
#include <vector>

#include "approximate/bspline.h"
#include "approximate/common_names.h"
#include "approximate/digital_image.h"
#include "approximate/gauss_image.h"
#include "approximate/skeleton_curve.h"
#include "common/error.h"
#include "common/parallel_for.h"

namespace qd::approximate {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Choice (P&T leave the control count to the user): one control point per 6 pixels of skeleton
// curve, between 4 and 40, and a second-difference penalty of 1% of the data weight per span.
constexpr double kPixelsPerControl = 6.0;
constexpr int kMinControls = 4, kMaxControls = 40;
constexpr double kSmoothing = 0.01;
constexpr int kDenseSamplesPerControl = 8;  // c_3D samples in the k-d tree, per control point
// Small-circle pole: its mean squared misfit must be below this share of the great circle's,
// and the samples this far from the pole.
constexpr double kSmallCircleGain = 0.25;
constexpr double kPoleClearance = 10.0 * kPi / 180.0;

// The Gauss image is a point: every target is the area-weighted mean normal.
class PlaneModel : public GaussModel {
 public:
  explicit PlaneModel(const Vec3& normal) : normal_(normal) {}
  Vec3 project(const Vec3&, int&) const override { return normal_; }
  TargetKind kind() const override { return TargetKind::Plane; }

 private:
  Vec3 normal_;
};

// c_3D(u) = R⁻¹ S(c_2D(u)) with S the inverse of Eq. 9 (see sphere_point).
class CurveModel : public GaussModel {
 public:
  CurveModel(const Eigen::Matrix3d& R, BSpline2 spline)
      : R_(R), spline_(std::move(spline)), cloud_{&points_} {
    const int M = std::max(64, kDenseSamplesPerControl * spline_.control_count());
    const int last = spline_.periodic() ? M : M - 1;  // open curves include u = 1
    step_ = 1.0 / last;
    for (int j = 0; j < M; ++j) {
      samples_.push_back(local(j * step_));
      points_.push_back(samples_.back().point());
    }
    // Half the distance from each sample to the nearest one outside its window.
    clearance_.assign(points_.size(), std::numeric_limits<double>::infinity());
    for (int j = 0; j < M; ++j)
      for (int k = 0; k < j; ++k) {
        const int apart = spline_.periodic() ? std::min(j - k, M - (j - k)) : j - k;
        if (apart <= kWindow) continue;
        const double half =
            0.5 * (points_[static_cast<size_t>(j)] - points_[static_cast<size_t>(k)]).norm();
        clearance_[static_cast<size_t>(j)] = std::min(clearance_[static_cast<size_t>(j)], half);
        clearance_[static_cast<size_t>(k)] = std::min(clearance_[static_cast<size_t>(k)], half);
      }
    tree_ = std::make_unique<Tree>(3, cloud_, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  }

  Vec3 project(const Vec3& n, int& hint) const override {
    const Vec3 m = R_ * n;
    const int index = nearest_sample(m, hint);
    hint = index;
    // Refine below the sampling step: safeguarded Newton on g(u) = m·S(c_2D(u)) (the cosine of
    // the angle) inside the two sampling intervals around the nearest sample, whose stored
    // values give the first step.
    double u = index * step_, lo = u - step_, hi = u + step_;
    if (!spline_.periodic()) lo = std::max(lo, 0.0), hi = std::min(hi, 1.0);
    Local p = samples_[static_cast<size_t>(index)];
    for (int it = 0; it < 40; ++it) {
      double g1 = 0, g2 = 0;
      p.cosine_derivatives(m, g1, g2);
      (g1 > 0 ? lo : hi) = u;
      double next = g2 < 0 ? u - g1 / g2 : lo - 1.0;
      // u itself is a bracket end: a converged step may round onto it, which must not count
      // as leaving the bracket.
      if (!(next >= lo && next <= hi)) next = 0.5 * (lo + hi);
      // Newton converges quadratically: after a step of 1e-9 sampling intervals the remaining
      // error is far below round-off, and so is the second-order term of the last step.
      if (std::abs(next - u) < 1e-9 * step_)
        return R_.transpose() * (p.point() + (next - u) * p.tangent());
      u = next;
      p = local(u, p);
    }
    return R_.transpose() * p.point();
  }

  TargetKind kind() const override {
    return spline_.periodic() ? TargetKind::ClosedCurve : TargetKind::Curve;
  }

 private:
  // A hint is trusted within this many samples on either side.
  static constexpr int kWindow = 4;

  // An angle with its sine and cosine.
  struct Angle {
    double a, s, c;

    static Angle of(double a) { return {a, std::sin(a), std::cos(a)}; }
    // Angle b from this one by angle addition, with the Taylor series of sin d and cos d
    // (d = b − a) exact to round-off for |d| <= 0.1 (first omitted terms below 1e-18): the
    // Newton steps move little, and this spares them the libm calls.
    Angle to(double b) const {
      const double d = b - a, d2 = d * d;
      if (!(std::abs(d) <= 0.1)) return of(b);
      const double sd =
          d * (1 + d2 * (-1.0 / 6 + d2 * (1.0 / 120 + d2 * (-1.0 / 5040 + d2 / 362880))));
      const double cd =
          1 +
          d2 * (-1.0 / 2 + d2 * (1.0 / 24 + d2 * (-1.0 / 720 + d2 * (1.0 / 40320 - d2 / 3628800))));
      return {b, s * cd + c * sd, c * cd - s * sd};
    }
  };

  // The curve S(θ(u), φ(u)) at one parameter: θ and φ (Eq. 9) and the first two derivatives of
  // c_2D(u) = (θ(u), φ(u)).
  struct Local {
    Angle theta, phi;
    Vec2 d1, d2;

    Vec3 point() const { return Vec3(phi.s * theta.c, phi.s * theta.s, phi.c); }
    Vec3 tangent() const {  // dS/du = S_θ θ' + S_φ φ'
      return Vec3(-phi.s * theta.s, phi.s * theta.c, 0) * d1.x() +
             Vec3(phi.c * theta.c, phi.c * theta.s, -phi.s) * d1.y();
    }
    // First and second derivative of g(u) = m·S(θ(u), φ(u)) by the chain rule, with
    // a = m·(cos θ, sin θ, 0) and b = m·(−sin θ, cos θ, 0):
    //   m·S = sin φ a + cos φ m_z,  m·S_θ = sin φ b,  m·S_φ = cos φ a − sin φ m_z,
    //   m·S_θθ = −sin φ a,  m·S_θφ = cos φ b,  m·S_φφ = −m·S.
    void cosine_derivatives(const Vec3& m, double& g1, double& g2) const {
      const double sp = phi.s, cp = phi.c;
      const double a = theta.c * m.x() + theta.s * m.y(), b = theta.c * m.y() - theta.s * m.x();
      const double S = sp * a + cp * m.z(), St = sp * b, Sp = cp * a - sp * m.z();
      const double t1 = d1.x(), p1 = d1.y();
      g1 = St * t1 + Sp * p1;
      g2 = -sp * a * t1 * t1 + 2 * cp * b * t1 * p1 - S * p1 * p1 + St * d2.x() + Sp * d2.y();
    }
  };

  Local local(double u) const {
    const CurvePoint c = spline_.eval(u);
    return {Angle::of(c.c.x()), Angle::of(c.c.y()), c.d1, c.d2};
  }
  // The same, with the sines and cosines from those of a nearby parameter.
  Local local(double u, const Local& near) const {
    const CurvePoint c = spline_.eval(u);
    return {near.theta.to(c.c.x()), near.phi.to(c.c.y()), c.d1, c.d2};
  }

  // The sample nearest to m among those within kWindow samples of sample j (the first of equals).
  int nearest_in_window(const Vec3& m, int j) const {
    const int M = static_cast<int>(points_.size());
    int best = j;
    double best_d2 = (m - points_[static_cast<size_t>(j)]).squaredNorm();
    for (int k = j - kWindow; k <= j + kWindow; ++k) {
      const int i = spline_.periodic() ? (k + M) % M : k;
      if (i < 0 || i >= M) continue;
      const double d2 = (m - points_[static_cast<size_t>(i)]).squaredNorm();
      if (d2 < best_d2 || (d2 == best_d2 && i < best)) best = i, best_d2 = d2;
    }
    return best;
  }

  // The sample nearest to m: the one nearest within its own window, reached from `hint` in a
  // few window steps; it is the nearest of all when m lies within its clearance (every sample
  // outside the window is then farther, by the triangle inequality). Otherwise, or without a
  // hint, the k-d tree's answer settled the same way, so the hint never changes the result
  // (short of exact ties between distant samples).
  int nearest_sample(const Vec3& m, int hint) const {
    constexpr int kMaxSteps = 4;
    for (int steps = 0, j = hint; j >= 0 && steps < kMaxSteps; ++steps) {
      const int next = nearest_in_window(m, j);
      if (next == j) {
        if ((m - points_[static_cast<size_t>(j)]).norm() < clearance_[static_cast<size_t>(j)])
          return j;
        break;
      }
      j = next;
    }
    uint32_t index = 0;
    double dist2 = 0;
    tree_->knnSearch(m.data(), 1, &index, &dist2);
    for (int j = static_cast<int>(index);;) {
      const int next = nearest_in_window(m, j);
      if (next == j) return j;
      j = next;
    }
  }

  struct Cloud {  // nanoflann dataset adaptor over the dense samples
    const std::vector<Vec3>* pts;
    size_t kdtree_get_point_count() const { return pts->size(); }
    double kdtree_get_pt(size_t i, size_t d) const { return (*pts)[i][static_cast<int>(d)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
      return false;
    }
  };
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>,
                                                   Cloud, 3, uint32_t>;

  Eigen::Matrix3d R_;
  BSpline2 spline_;
  double step_ = 0;
  std::vector<Local> samples_;  // dense samples of the curve at u = j·step_
  std::vector<Vec3> points_;    // their points S, in the k-d tree
  std::vector<double> clearance_;
  Cloud cloud_;
  std::unique_ptr<Tree> tree_;
};

// Steps 1.3–1.4: digital image, skeleton, ordered curve and its B-spline c_2D in (θ, φ).
// Returns false when the image has no usable skeleton (fewer than two ridge points).
bool fit_skeleton_spline(const std::vector<Vec2>& theta_phi, const std::vector<double>& areas,
                         const GaussFrame& frame, std::unique_ptr<BSpline2>& spline) {
  DigitalImage image = rasterise(theta_phi, areas, frame.closed, frame.gap, kGapOutlierShare);
  goshtasby_field(image);
  OrderedSkeleton curve = order_skeleton(skeleton_pixels(image), image.width, image.periodic);
  if (!curve.closed) {
    std::vector<Vec2> samples;
    for (size_t i = 0; i < theta_phi.size(); ++i) {
      const Vec2 px = image.to_pixel(theta_phi[i]);
      if (areas[i] > 0 && (image.periodic || (px.x() >= 0 && px.x() <= image.width)) &&
          px.y() >= 0 && px.y() <= image.height)  // stray outliers left out of the image
        samples.push_back(px);
    }
    extend_ends(curve.points, samples, 2.0 * image.effect_radius,
                image.periodic ? image.width : 0.0, image.effect_radius);
  }
  if (curve.points.size() < 2) return false;
  double length_px =
      curve.closed ? (curve.points.front() + curve.shift - curve.points.back()).norm() : 0;
  for (size_t k = 1; k < curve.points.size(); ++k)
    length_px += (curve.points[k] - curve.points[k - 1]).norm();
  std::vector<Vec2> points;
  for (const Vec2& px : curve.points) points.push_back(image.to_theta_phi(px));
  const Vec2 shift = curve.shift * image.pixel;
  const std::vector<double> params = chord_length_params(points, curve.closed, shift);
  const int controls = std::clamp(static_cast<int>(std::lround(length_px / kPixelsPerControl)),
                                  kMinControls, kMaxControls);
  const double smoothing = kSmoothing * static_cast<double>(points.size()) / controls;
  spline = std::make_unique<BSpline2>(
      fit_bspline(points, params, controls, smoothing, curve.closed, shift));
  return true;
}

}  // namespace

std::vector<Vec3> project_normals(const GaussModel& model, const std::vector<Vec3>& normals,
                                  size_t threads) {
  std::vector<Vec3> targets(normals.size());
  parallel_ranges(normals.size(), threads, kRangeChunk, [&](size_t first, size_t last) {
    int hint = -1;  // successive samples are usually neighbours (see GaussModel::project)
    for (size_t i = first; i < last; ++i) targets[i] = model.project(normals[i], hint);
  });
  return targets;
}

namespace {

// Steps 1.2–1.4 from the samples' moments (Step 1.1): c_3D, or the plane's normal.
std::shared_ptr<const GaussModel> fitted_model(const std::vector<Vec3>& normals,
                                               const std::vector<double>& areas,
                                               const GaussMoments& moments) {
  if (fills_sphere(moments))
    throw Error(
        "patch normals fill the sphere: it is far from developable; split it into "
        "smaller, nearly developable patches");
  std::unique_ptr<BSpline2> spline;
  Eigen::Matrix3d R;
  if (!is_point_like(normals, areas, moments)) {
    // Step 1.2: rotation R of Eq. 9 and the mapped samples.
    Vec3 pole = best_great_circle_pole(normals, areas, moments);
    // Choice beyond Eq. 9: the Gauss image of a cone is a small circle, which no great circle
    // follows (for a full cone with normals < 55° from the axis the best great circle even
    // cuts through it). When the best small circle fits far better and the samples stay
    // clear of its pole (Eq. 9's θ is ill-conditioned there), its pole is used instead.
    double small_misfit = 0;
    const Vec3 small_pole = best_small_circle_pole(normals, areas, moments, small_misfit);
    if (small_misfit < kSmallCircleGain * great_circle_misfit(normals, areas, moments, pole) &&
        clear_of_poles(normals, areas, small_pole, kPoleClearance))
      pole = small_pole;
    const GaussFrame frame = gauss_frame(normals, areas, pole);
    R = frame.R;
    std::vector<Vec2> theta_phi_samples(normals.size());
    for (size_t i = 0; i < normals.size(); ++i) theta_phi_samples[i] = theta_phi(R * normals[i]);
    if (!fit_skeleton_spline(theta_phi_samples, areas, frame, spline))
      throw Error(
          "no skeleton curve could be traced in the Gauss image of a patch: it is far "
          "from developable; split it into smaller, nearly developable patches");
  }
  if (spline) return std::make_shared<CurveModel>(R, std::move(*spline));
  // Step 1 for a planar patch: the Gauss image is a point
  return std::make_shared<PlaneModel>(moments.resultant.normalized());
}

}  // namespace

std::shared_ptr<const GaussModel> fit_model(const std::vector<Vec3>& normals,
                                            const std::vector<double>& areas) {
  return fitted_model(normals, areas, gauss_moments(normals, areas));
}

TargetFit fit_targets(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                      size_t threads) {
  const GaussMoments moments = gauss_moments(normals, areas);  // Step 1.1 (throws on bad input)
  TargetFit fit;
  fit.model = fitted_model(normals, areas, moments);
  // Steps 1.5–1.6: nearest point of c_3D and the area-weighted mean residual angle.
  fit.targets = project_normals(*fit.model, normals, threads);
  double weighted = 0;
  for (size_t i = 0; i < normals.size(); ++i) {
    if (areas[i] > 0)
      weighted += areas[i] * std::atan2(normals[i].cross(fit.targets[i]).norm(),
                                        normals[i].dot(fit.targets[i]));
  }
  fit.residual_deg = weighted / moments.total_area * 180.0 / kPi;
  return fit;
}

}  // namespace qd::approximate
