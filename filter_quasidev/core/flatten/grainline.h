// The grainline of a pattern piece: the direction on the flat piece that the straight grain of
// the cloth follows. Designers model garments upright and the straight grain runs vertically on
// the body, so it is the model's up direction carried onto the piece: per face, `up` projected
// into the face's plane and mapped by the face's linear map from 3D to the flat piece (the one
// its three corners define), summed weighted by area. Where that says little — the area-weighted
// mean of the mapped up direction shorter than kWeakGrain, as on a piece lying nearly across
// `up` (a hat's crown), or whose slopes cancel (a tube lying on its side) — the grain runs along
// the piece's longest (principal) axis instead, pointing the way `up` leans if it does.
#pragma once

#include <Eigen/Core>

#include "common/mesh.h"
#include "flatten/common_names.h"

namespace qd::flatten {

constexpr double kWeakGrain = 0.3;  // the mapped up direction per unit area: sin 17°

// Unit direction of the principal axis of the points (rows): the longest one of their
// covariance, sign as Eigen's eigen solver gives it.
Eigen::Vector2d principal_axis(const Eigen::MatrixX2d& points);

// Unit grain direction on the flat piece (V, F its 3D faces, uv its flat positions per vertex).
// up = 0: the principal axis, pointing the way +y leans on the piece, for garments whose
// pieces do not hang along one axis (sleeves of a T-pose run across the body's up direction).
Eigen::Vector2d grain_direction(const Positions& V, const Triangles& F, const Eigen::MatrixX2d& uv,
                                const Eigen::Vector3d& up);

}  // namespace qd::flatten
