// The initial flattening of a disk-shaped piece, before ARAP: its boundary first, then its
// interior (Sawhney & Crane 2017, "Boundary First Flattening", ACM TOG 37(1)).
//  1. Boundary scale factors u = 0 (boundary lengths kept, which makes the result exact for a
//     developable piece): the conformal factor of the interior solves the discrete Yamabe
//     equation ΔU = K with U = 0 on the boundary, L_II u_I = −Ω_I (Ω = 2π − angle sum at an
//     interior vertex, L the cotangent Laplacian, uᵀLu = ∫|∇u|²).
//  2. Boundary curvature after flattening, from the Neumann derivative of u (the discrete
//     Dirichlet-to-Neumann map): κ̃_B = κ_B + (L u)_B with κ = π − angle sum at a boundary
//     vertex; Σ κ̃ = 2π by Gauss–Bonnet.
//  3. The closed curve with these turning angles and the boundary's lengths (boundary_curve.h).
//  4. The interior as the harmonic extension of both coordinates, L_II x_I = −L_IB x_B
//     (a Tutte/harmonic embedding whose boundary shape is computed, not guessed).
// Only scalar systems: one factorisation of L_II serves steps 1 and 4, where LSCM (Lévy et al.
// 2002) with two pinned vertices needs the coupled 2n×2n system, several times slower to
// factorise (docs/measurements-behind-the-code.md).
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "common/solver_kind.h"
#include "flatten/common_names.h"
#include "flatten/flat_triangles.h"

namespace qd::flatten {

// V, F: the piece (a disk); g its face geometry and L its cotangent Laplacian; loop its
// boundary in face order. Returns one row (u, v) per vertex, in model units.
Eigen::MatrixX2d initial_layout(const Positions& V, const Triangles& F, const FlatTriangles& g,
                                const Eigen::SparseMatrix<double>& L, const std::vector<int>& loop,
                                SolverKind solver);

}  // namespace qd::flatten
