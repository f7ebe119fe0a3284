// Each triangle laid flat in its own plane, and what the flattening steps need of it.
// Corner coordinates in an isometric 2D frame: x0 = (0, 0), x1 = (|v1 − v0|, 0), x2 above the
// x axis; the 3D→2D map of a face is then the 2×2 Jacobian J = [u1 − u0, u2 − u0]·E⁻¹ with
// E = [x1 − x0, x2 − x0] (the per-triangle linear map of Liu et al. 2008).
#pragma once

#include <vector>

#include "common/mesh.h"
#include "flatten/common_names.h"

namespace qd::flatten {

struct FlatTriangles {
  std::vector<Eigen::Matrix<double, 2, 3>> corner;  // per face: x0, x1, x2 (columns)
  std::vector<Eigen::Matrix2d> inverse_edges;       // per face: E⁻¹ (zero for a degenerate face)
  Eigen::VectorXd area;                             // per face, 3D area
  Eigen::Matrix<double, Eigen::Dynamic, 3> angle;   // per face and corner: interior angle
  // Per face and corner k: ½ cot of the angle at k, the weight of the edge opposite k in the
  // cotangent Laplacian (Pinkall & Polthier 1993); 0 for a degenerate face.
  Eigen::Matrix<double, Eigen::Dynamic, 3> half_cot;
};

FlatTriangles flat_triangles(const Positions& V, const Triangles& F);

// J of face f for the flat positions uv (one row per vertex).
Eigen::Matrix2d face_jacobian(const FlatTriangles& g, const Triangles& F,
                              const Eigen::MatrixX2d& uv, int f);

}  // namespace qd::flatten
