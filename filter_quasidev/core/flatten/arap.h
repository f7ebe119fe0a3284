// As-rigid-as-possible flattening by local/global iterations (Liu, Zhang, Xu, Gotsman, Gortler
// 2008, "A local/global approach to mesh parameterization", SGP). Their energy with cotangent
// weights, written per face with the identity Σ_k ½cot θ_k |M e_k|² = A‖M‖²_F:
//     E(u, R) = Σ_t A_t ‖J_t − R_t‖²_F,    R_t ∈ SO(2).
// Local step: R_t = the rotation nearest J_t; for a 2×2 matrix that is the rotation by
// atan2(J10 − J01, J00 + J11), never a reflection. Global step: L u = b with L the
// cotangent Laplacian and b_i = Σ_t Σ_{j∈t} ½cot θ_ij R_t (x_i − x_j); L does not depend on
// the iterate, so it is factorised once per piece (one vertex pinned: E is blind to
// translation) and each iteration costs one solve with two right-hand sides.
#pragma once

#include <Eigen/SparseCore>
#include <functional>
#include <string>

#include "common/solver_kind.h"
#include "flatten/common_names.h"
#include "flatten/flat_triangles.h"

namespace qd::flatten {

struct ArapSettings {
  int max_iterations = 100;
  double tolerance = 1e-4;  // stop when |E_prev − E| ≤ tolerance · E_prev
  SolverKind solver = SolverKind::Auto;
};

struct ArapOutcome {
  int iterations = 0;       // global steps taken
  double energy = 0;        // E / Σ A_t after the last step: area-weighted mean ‖J − R‖²_F
  std::string stop_reason;  // "converged", "exact", "iteration cap"
};

// uv: the starting flattening (one row per vertex), replaced by the result. L: the cotangent
// Laplacian of F. iteration(k) is called after global step k (1-based).
ArapOutcome arap(const Triangles& F, const FlatTriangles& g, const Eigen::SparseMatrix<double>& L,
                 Eigen::MatrixX2d& uv, const ArapSettings& settings,
                 const std::function<void(int)>& iteration = {});

}  // namespace qd::flatten
