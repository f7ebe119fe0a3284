#include "flatten/arap.h"

#include <cassert>
#include <cmath>
#include <vector>

#include "flatten/cotangent_laplacian.h"
#include "flatten/ordered_cholesky.h"

namespace qd::flatten {

namespace {

// Below this E / Σ A the flattening is an isometry to rounding: nothing is left to improve.
constexpr double kExactEnergy = 1e-24;

// The rotation nearest to J in the Frobenius norm (the local step).
Eigen::Matrix2d nearest_rotation(const Eigen::Matrix2d& J) {
  const double c = J(0, 0) + J(1, 1), s = J(1, 0) - J(0, 1), r = std::hypot(c, s);
  if (r == 0) return Eigen::Matrix2d::Identity();
  Eigen::Matrix2d R;
  R << c / r, -s / r, s / r, c / r;
  return R;
}

// Per face, Y_t = X_t K_t: column k is Σ_j ½cot θ_kj (x_k − x_j), so that face t adds R_t Y_t(:, k)
// to b at its corner k (the global step).
std::vector<Eigen::Matrix<double, 2, 3>> weighted_frame_edges(const FlatTriangles& g) {
  std::vector<Eigen::Matrix<double, 2, 3>> Y(g.corner.size());
  for (size_t f = 0; f < Y.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;  // weight of edge (k, i) is half_cot at j
      const Eigen::Matrix<double, 2, 3>& x = g.corner[f];
      const auto fi = static_cast<Eigen::Index>(f);
      Y[f].col(k) =
          g.half_cot(fi, j) * (x.col(k) - x.col(i)) + g.half_cot(fi, i) * (x.col(k) - x.col(j));
    }
  return Y;
}

}  // namespace

ArapOutcome arap(const Triangles& F, const FlatTriangles& g, const Eigen::SparseMatrix<double>& L,
                 Eigen::MatrixX2d& uv, const ArapSettings& settings,
                 const std::function<void(int)>& iteration) {
  const int n = static_cast<int>(uv.rows()), pinned = 0;
  assert(L.rows() == n && L.cols() == n && g.corner.size() == static_cast<size_t>(F.rows()));
  std::vector<int> free_index(static_cast<size_t>(n));
  for (int v = 0; v < n; ++v) free_index[v] = v == pinned ? -1 : v - (v > pinned);
  const OrderedCholesky solver(sparse_block(L, free_index, n - 1, free_index, n - 1),
                               settings.solver, Solves::Many);
  const Eigen::VectorXd pin_column = L.col(pinned);
  const std::vector<Eigen::Matrix<double, 2, 3>> Y = weighted_frame_edges(g);
  const double total_area = g.area.sum();

  std::vector<Eigen::Matrix2d> R(static_cast<size_t>(F.rows()));
  ArapOutcome out;
  double previous = 0;
  for (;;) {
    double energy = 0;  // local step
    for (int f = 0; f < F.rows(); ++f) {
      const Eigen::Matrix2d J = face_jacobian(g, F, uv, f);
      R[f] = nearest_rotation(J);
      energy += g.area(f) * (J - R[f]).squaredNorm();
    }
    out.energy = energy / total_area;
    if (out.energy <= kExactEnergy)
      out.stop_reason = "exact";
    else if (out.iterations > 0 && previous - energy <= settings.tolerance * previous)
      out.stop_reason = "converged";
    else if (out.iterations >= settings.max_iterations)
      out.stop_reason = "iteration cap";
    if (!out.stop_reason.empty()) return out;
    previous = energy;

    Eigen::MatrixX2d b = Eigen::MatrixX2d::Zero(n, 2);  // global step
    for (int f = 0; f < F.rows(); ++f)
      for (int k = 0; k < 3; ++k) b.row(F(f, k)) += (R[f] * Y[f].col(k)).transpose();
    b -= pin_column * uv.row(pinned);
    Eigen::MatrixX2d free_b(n - 1, 2);
    for (int v = 0; v < n; ++v)
      if (free_index[v] >= 0) free_b.row(free_index[v]) = b.row(v);
    const Eigen::MatrixXd x = solver.solve(free_b);
    for (int v = 0; v < n; ++v)
      if (free_index[v] >= 0) uv.row(v) = x.row(free_index[v]);
    ++out.iterations;
    if (iteration) iteration(out.iterations);
  }
}

}  // namespace qd::flatten
