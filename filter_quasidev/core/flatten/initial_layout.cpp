#include "flatten/initial_layout.h"

#include <cmath>
#include <optional>

#include "flatten/boundary_curve.h"
#include "flatten/cotangent_laplacian.h"
#include "flatten/ordered_cholesky.h"

namespace qd::flatten {

Eigen::MatrixX2d initial_layout(const Positions& V, const Triangles& F, const FlatTriangles& g,
                                const Eigen::SparseMatrix<double>& L, const std::vector<int>& loop,
                                SolverKind solver) {
  const int n = static_cast<int>(V.rows()), m = static_cast<int>(loop.size());
  std::vector<int> interior(static_cast<size_t>(n), 0), boundary(static_cast<size_t>(n), -1);
  for (int i = 0; i < m; ++i) boundary[loop[i]] = i;
  int ni = 0;
  for (int v = 0; v < n; ++v) interior[v] = boundary[v] < 0 ? ni++ : -1;

  Eigen::VectorXd angle_sum = Eigen::VectorXd::Zero(n);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) angle_sum(F(f, k)) += g.angle(f, k);
  const double pi = std::acos(-1.0);
  Eigen::VectorXd turning(m), defect(ni);
  for (int v = 0; v < n; ++v) {
    if (boundary[v] >= 0)
      turning(boundary[v]) = pi - angle_sum(v);  // κ_B
    else
      defect(interior[v]) = 2 * pi - angle_sum(v);  // Ω_I
  }

  const Eigen::SparseMatrix<double> L_IB = sparse_block(L, interior, ni, boundary, m);
  std::optional<OrderedCholesky> L_II;
  if (ni > 0) {
    L_II.emplace(sparse_block(L, interior, ni, interior, ni), solver, Solves::Few);
    const Eigen::VectorXd u = L_II->solve(-defect);  // step 1
    turning += L_IB.transpose() * u;                 // step 2: κ̃_B = κ_B + L_BI u_I
  }
  Eigen::VectorXd lengths(m);
  for (int i = 0; i < m; ++i) lengths(i) = (V.row(loop[(i + 1) % m]) - V.row(loop[i])).norm();
  const Eigen::MatrixX2d curve = closed_boundary_curve(lengths, turning);  // step 3

  Eigen::MatrixX2d uv(n, 2);
  const Eigen::MatrixX2d inside =
      L_II ? Eigen::MatrixX2d(L_II->solve(-(L_IB * curve))) : Eigen::MatrixX2d(0, 2);  // step 4
  for (int v = 0; v < n; ++v)
    uv.row(v) = boundary[v] >= 0 ? curve.row(boundary[v]) : inside.row(interior[v]);
  return uv;
}

}  // namespace qd::flatten
