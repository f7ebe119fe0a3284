// Fitting a cone proxy (cone_proxy.h) to the normals of a set of faces, and its fit error.
//
// D-Charts fits the proxy by least squares on N·n_t − cos θ over the chart's faces. For fixed N
// the best cos θ is the mean of N·n_t, and the residual is Nᵀ C N with C the area-weighted
// covariance of the normals, so the least-squares axis is C's eigenvector of the smallest
// eigenvalue. For a narrow band of normals (a strip of a cylinder) the two smallest eigenvalues
// are both near zero and that axis is ill-conditioned; for a plane all three are. So every
// eigenvector, the mean normal and any axes the caller adds (a chart's previous axis) are tried.
// Each axis gives two cones: the midrange apex angle of the normals' angles to it, which makes
// the largest error smallest, and their mean, which makes the root mean square smallest.
// better_fit() picks among them: a cone within the limit wins, and among those the smallest
// largest error (ties, within kAxisTie, to the smaller apex angle, so a flat chart is a plane
// and not a cylinder through its one normal); over the limit the smallest root mean square
// wins, so a few faces far off do not tilt the cone for all the others.
#pragma once

#include <vector>

#include "segment/cone_proxy.h"
#include "segment/face_geometry.h"
#include "segment/normal_moments.h"

namespace qd::segment {

constexpr double kAxisTie = 1e-6;  // radians

struct ConeFit {
  ConeProxy proxy;
  double max_error = 0.0;  // largest |∠(n_t, N) − θ| over the faces, radians
  double rms_error = 0.0;  // area-weighted root mean square of the same, radians
};

NormalMoments normal_moments(const FaceGeometry& g, const std::vector<int>& faces);

// The errors of a given cone over `faces`.
ConeFit measure_cone(const FaceGeometry& g, const std::vector<int>& faces, const ConeProxy& cone);

// The best cone (as above) over `faces`, which must not be empty. limit: radians.
ConeFit fit_cone(const FaceGeometry& g, const std::vector<int>& faces, double limit,
                 const std::vector<Vec3>& extra_axes = {});

// Whether fit a is better than b for this limit (as above).
bool better_fit(const ConeFit& a, const ConeFit& b, double limit);

// A lower bound of the largest error of any cone over faces with these moments: for any N and θ,
// |N·n − cos θ| ≤ |∠(n, N) − θ|, so the mean square of the latter is at least Nᵀ C N ≥ λ_min(C).
double max_error_lower_bound(const NormalMoments& m);

}  // namespace qd::segment
