// A closed plane curve from its edge lengths and turning angles: the boundary of a flattening
// built before its interior (Sawhney & Crane 2017, "Boundary First Flattening", ACM TOG 37(1),
// its curve construction). Edge i runs from vertex i to vertex i + 1 (cyclically) in direction
// φ_i = Σ_{j≤i} κ_j, and γ_{i+1} = γ_i + l̃_i (cos φ_i, sin φ_i). The lengths are then adjusted
// as little as possible so the curve closes: minimise Σ (l̃_i − l_i)²/l_i subject to
// Σ l̃_i T_i = 0, whose solution is l̃ = l − N⁻¹Tᵀ(T N⁻¹ Tᵀ)⁻¹ T l with N = diag(1/l_i) and T
// the 2×m matrix of the edge directions T_i.
#pragma once

#include <Eigen/Core>

namespace qd::flatten {

// lengths: target length of each edge (> 0); turning: exterior angle κ_i at each vertex
// (Σ κ_i = 2π for a curve turning counter-clockwise). Returns one row per vertex, vertex 0 at
// the origin.
Eigen::MatrixX2d closed_boundary_curve(const Eigen::VectorXd& lengths,
                                       const Eigen::VectorXd& turning);

}  // namespace qd::flatten
