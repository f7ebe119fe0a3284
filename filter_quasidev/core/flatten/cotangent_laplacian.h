// The cotangent Laplacian (Pinkall & Polthier 1993): L_ij = −Σ ½ cot of the angles opposite
// edge ij, L_ii = −Σ_j L_ij, so that uᵀLu = ∫|∇u|² for a piecewise linear u. Symmetric
// positive semi-definite, constants in its kernel.
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "flatten/flat_triangles.h"

namespace qd::flatten {

Eigen::SparseMatrix<double> cotangent_laplacian(const Triangles& F, const FlatTriangles& g,
                                                int vertex_count);

// The block of M with the rows and columns whose number in `row` / `column` is ≥ 0, renumbered
// by it (row[i] = new row of row i or −1; `rows`, `columns` the new sizes).
Eigen::SparseMatrix<double> sparse_block(const Eigen::SparseMatrix<double>& M,
                                         const std::vector<int>& row, int rows,
                                         const std::vector<int>& column, int columns);

}  // namespace qd::flatten
