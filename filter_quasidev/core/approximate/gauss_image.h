// The discrete extended Gauss image (DEGI) of one patch (§5.1): unit face normals n_f weighted
// by face area a_f, its shape tests (point-like, sphere-filling) and the rotation R of Eq. 9 that
// puts the best great circle on the equator and the widest empty θ-gap on the θ = 0/2π seam.
//   Inputs everywhere: normals (unit) and areas (>= 0, zero-area samples weigh 0).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "approximate/bspline.h"
#include "approximate/common_names.h"
#include "common/mesh.h"

namespace qd::approximate {

// Area-weighted moments of the DEGI.
struct GaussMoments {
  double total_area = 0;                              // Σ a
  Vec3 resultant = Vec3::Zero();                      // Σ a n
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();  // Σ a n nᵀ
};

// Checks the input (sizes, finite unit normals, areas >= 0, at least 3 positive-area samples)
// and returns the moments. Throws qd::common::Error with a user-facing message otherwise.
GaussMoments gauss_moments(const std::vector<Vec3>& normals, const std::vector<double>& areas);

// True when the samples fill the sphere: |Σ a n|/Σ a < 0.1 and the smallest eigenvalue of
// Σ a n nᵀ / Σ a > 0.2 (a uniform sphere gives 0 and 1/3; a hemisphere bowl 0.5 and 1/4;
// a full cylinder tube 0 and 0).
bool fills_sphere(const GaussMoments& m);

// True when the Gauss image is a point (planar patch, possibly noisy): see the thresholds at
// the definition.
bool is_point_like(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                   const GaussMoments& m);

// Pole p of the great circle minimising Σ a |asin(n·p)| (Eq. 9's "minimal summarization of
// geodesic distances"), sign fixed by the data.
Vec3 best_great_circle_pole(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                            const GaussMoments& m);

// Pole of the best small circle in the least-squares sense: the plane Σ a (n·c − d)² → min
// cuts the sphere in that circle, so c is the smallest-eigenvalue eigenvector of the
// area-weighted covariance of the normals; `misfit` is that eigenvalue (mean squared
// distance to the plane). Sign as for the great circle.
Vec3 best_small_circle_pole(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                            const GaussMoments& m, double& misfit);

// Mean squared distance Σ a (n·p)² / Σ a of the samples to the plane of the great circle with pole
// p.
double great_circle_misfit(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                           const GaussMoments& m, const Vec3& pole);

// The rotation R of Eq. 9 and what the θ coverage says about the curve.
struct GaussFrame {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // rows e1, e2, p: maps p to +z
  double gap = 0;       // width of the widest empty θ-gap, centred on the seam: the samples
                        // lie in θ ∈ [gap/2, 2π − gap/2] (up to kGapOutlierShare of the area)
  bool closed = false;  // samples cover all θ (a tube): the skeleton curve is closed
};

// Share of the total area that may lie inside an "empty" θ-gap (stray outlier normals must
// not close the gap of a partial cylinder).
constexpr double kGapOutlierShare = 0.01;

// R maps the pole to +z and is then turned about z so the widest empty θ-gap of the
// positive-area samples is centred on the θ = 0/2π seam.
GaussFrame gauss_frame(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                       const Vec3& pole);

// True when at most kGapOutlierShare of the area lies within `clearance` (radians) of the
// poles ±pole: Eq. 9's θ is ill-conditioned there ("kept away from the north and south points").
bool clear_of_poles(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                    const Vec3& pole, double clearance);

// Eq. 9: (θ, φ) of a unit vector m given in the rotated frame (θ ∈ [0, 2π), φ ∈ [0, π]),
// and its inverse.
Vec2 theta_phi(const Vec3& m);
Vec3 sphere_point(double theta, double phi);

}  // namespace qd::approximate
