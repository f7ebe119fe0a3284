// Step 1 of the paper (§5.1): DEGI -> rotation R (Eq. 9) -> digital image and skeleton
// (Eqs. 10–12) -> B-spline c_2D -> spherical curve c_3D = R⁻¹ S(c_2D) -> target normals.
#include "target_normals.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bspline.h"
#include "digital_image.h"
#include "error.h"
#include "gauss_image.h"
#include "skeleton_curve.h"

namespace qd {

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
  Vec3 project(const Vec3&) const override { return normal_; }
  std::string kind() const override { return "plane"; }

 private:
  Vec3 normal_;
};

// c_3D(u) = R⁻¹ S(c_2D(u)) with S the inverse of Eq. 9 (see sphere_point).
class CurveModel : public GaussModel {
 public:
  CurveModel(const Eigen::Matrix3d& R, BSpline2 spline)
      : R_(R), spline_(std::move(spline)), cloud_{&dense_} {
    const int M = std::max(64, kDenseSamplesPerControl * spline_.control_count());
    const int last = spline_.periodic() ? M : M - 1;  // open curves include u = 1
    step_ = 1.0 / last;
    for (int j = 0; j < M; ++j) dense_.push_back(local_point(j * step_));
    tree_ = std::make_unique<Tree>(3, cloud_, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  }

  Vec3 project(const Vec3& n) const override {
    const Vec3 m = R_ * n;
    uint32_t index = 0;
    double dist2 = 0;
    tree_->knnSearch(m.data(), 1, &index, &dist2);
    // Refine below the sampling step: safeguarded Newton on g(u) = m·S(c_2D(u)) (the cosine of
    // the angle) inside the two sampling intervals around the nearest sample.
    double u = index * step_, lo = u - step_, hi = u + step_;
    if (!spline_.periodic()) lo = std::max(lo, 0.0), hi = std::min(hi, 1.0);
    for (int it = 0; it < 40; ++it) {
      double g1 = 0, g2 = 0;
      cosine_derivatives(m, u, g1, g2);
      (g1 > 0 ? lo : hi) = u;
      double next = g2 < 0 ? u - g1 / g2 : lo - 1.0;
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      // Newton converges quadratically: after a step of 1e-9 sampling intervals the remaining
      // error is far below round-off.
      const bool done = std::abs(next - u) < 1e-9 * step_;
      u = next;
      if (done) break;
    }
    return R_.transpose() * local_point(u);
  }

  std::string kind() const override { return spline_.periodic() ? "closed curve" : "curve"; }

 private:
  struct Cloud {  // nanoflann dataset adaptor over the dense samples
    const std::vector<Vec3>* pts;
    size_t kdtree_get_point_count() const { return pts->size(); }
    double kdtree_get_pt(size_t i, size_t d) const { return (*pts)[i][static_cast<int>(d)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const { return false; }
  };
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>,
                                                   Cloud, 3, uint32_t>;

  Vec3 local_point(double u) const {
    const Vec2 c = spline_.eval(u).c;
    return sphere_point(c.x(), c.y());
  }

  // First and second derivative of g(u) = m·S(θ(u), φ(u)) by the chain rule through Eq. 9.
  void cosine_derivatives(const Vec3& m, double u, double& g1, double& g2) const {
    const CurvePoint p = spline_.eval(u);
    const double st = std::sin(p.c.x()), ct = std::cos(p.c.x());
    const double sp = std::sin(p.c.y()), cp = std::cos(p.c.y());
    const Vec3 S(sp * ct, sp * st, cp);
    const Vec3 St(-sp * st, sp * ct, 0), Sp(cp * ct, cp * st, -sp);
    const Vec3 Stt(-sp * ct, -sp * st, 0), Stp(-cp * st, cp * ct, 0);
    const double t1 = p.d1.x(), p1 = p.d1.y();
    const Vec3 dS = St * t1 + Sp * p1;
    const Vec3 ddS = Stt * (t1 * t1) + Stp * (2 * t1 * p1) - S * (p1 * p1) + St * p.d2.x() +
                     Sp * p.d2.y();
    g1 = m.dot(dS);
    g2 = m.dot(ddS);
  }

  Eigen::Matrix3d R_;
  BSpline2 spline_;
  double step_ = 0;
  std::vector<Vec3> dense_;
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
  double length_px = curve.closed ? (curve.points.front() + curve.shift - curve.points.back()).norm() : 0;
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

TargetFit fit_targets(const std::vector<Vec3>& normals, const std::vector<double>& areas) {
  const GaussMoments moments = gauss_moments(normals, areas);  // Step 1.1 (throws on bad input)
  if (fills_sphere(moments))
    throw Error("patch normals fill the sphere: it is far from developable; split it into "
                "smaller, nearly developable patches");
  TargetFit fit;
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
      throw Error("no skeleton curve could be traced in the Gauss image of a patch: it is far "
                  "from developable; split it into smaller, nearly developable patches");
  }
  if (spline)
    fit.model = std::make_shared<CurveModel>(R, std::move(*spline));
  else  // Step 1 for a planar patch: the Gauss image is a point
    fit.model = std::make_shared<PlaneModel>(moments.resultant.normalized());

  // Steps 1.5–1.6: nearest point of c_3D and the area-weighted mean residual angle.
  fit.targets.resize(normals.size());
  double weighted = 0;
  for (size_t i = 0; i < normals.size(); ++i) {
    fit.targets[i] = fit.model->project(normals[i]);
    if (areas[i] > 0)
      weighted += areas[i] * std::atan2(normals[i].cross(fit.targets[i]).norm(),
                                        normals[i].dot(fit.targets[i]));
  }
  fit.residual_deg = weighted / moments.total_area * 180.0 / kPi;
  return fit;
}

}  // namespace qd
