// Least-squares cubic B-splines (Piegl & Tiller ch. 9.4.1); see bspline.h.
#include "approximate/bspline.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "approximate/common_names.h"
#include "common/error.h"

namespace qd::approximate {

namespace {

constexpr int kDegree = 3;

// a / b with 0/0 := 0 (the convention of the Cox-de Boor recursion, P&T Eq. 2.5).
double safe_div(double a, double b) { return b == 0.0 ? 0.0 : a / b; }

// Uniform cubic B-spline weights and their derivatives in the local parameter t ∈ [0, 1).
void uniform_cubic_basis(double t, double N[4], double dN[4], double ddN[4]) {
  const double s = 1.0 - t;
  N[0] = s * s * s / 6.0;
  N[1] = (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0;
  N[2] = (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0;
  N[3] = t * t * t / 6.0;
  dN[0] = -s * s / 2.0;
  dN[1] = (9.0 * t * t - 12.0 * t) / 6.0;
  dN[2] = (-9.0 * t * t + 6.0 * t + 3.0) / 6.0;
  dN[3] = t * t / 2.0;
  ddN[0] = s;
  ddN[1] = 3.0 * t - 2.0;
  ddN[2] = -3.0 * t + 1.0;
  ddN[3] = t;
}

}  // namespace

BSpline2::BSpline2(std::vector<Vec2> control, bool periodic, const Vec2& period_shift)
    : control_(std::move(control)), periodic_(periodic), shift_(period_shift) {
  const int n = control_count();
  if (n < kDegree + 1) throw Error("internal: a cubic B-spline needs at least 4 control points");
  const int spans = periodic_ ? n : n - kDegree;
  if (!periodic_) {  // clamped knot vector with uniform interior knots on [0, 1] (n + 4 knots)
    knots_.assign(n + kDegree + 1, 0.0);
    for (int i = 0; i <= spans; ++i) knots_[i + kDegree] = static_cast<double>(i) / spans;
    for (int i = n; i < n + kDegree + 1; ++i) knots_[i] = 1.0;
  }
  // Power form of every span from the value and derivatives at its start (the third
  // derivative is constant on a span: the change of the second, which is continuous at the
  // simple interior knots, over it).
  for (int k = 0; k < spans; ++k) {
    const double u0 = static_cast<double>(k) / spans, u1 = static_cast<double>(k + 1) / spans;
    const CurvePoint a = eval_from_basis(u0);
    const Vec2 d3 = (eval_from_basis(u1).d2 - a.d2) / (u1 - u0);
    Piece piece{u0, Eigen::Matrix<double, 2, 4>()};
    piece.coef << a.c, a.d1, 0.5 * a.d2, d3 / 6.0;
    pieces_.push_back(piece);
  }
}

void BSpline2::basis(double u, int& first, double N[4], double dN[4], double ddN[4]) const {
  const int n = control_count();
  if (periodic_) {
    const double s = (u - std::floor(u)) * n;
    const int k = std::min(static_cast<int>(s), n - 1);
    uniform_cubic_basis(s - k, N, dN, ddN);
    for (int j = 0; j < 4; ++j) {  // chain rule d/du = n d/dt
      dN[j] *= n;
      ddN[j] *= static_cast<double>(n) * n;
    }
    first = k;
    return;
  }
  // Open clamped curve: Cox-de Boor recursion (P&T Eqs. 2.5 and 2.9) on the span k with
  // knots_[k] <= u < knots_[k+1]; B[q][r] = N_{k-q+r, q}(u).
  u = std::clamp(u, 0.0, 1.0);
  const std::vector<double>& U = knots_;
  const int k = std::min(kDegree + static_cast<int>(u * (n - kDegree)), n - 1);
  double B[4][4] = {{1.0}};
  auto value = [&](int q, int i) { return (i < k - q || i > k) ? 0.0 : B[q][i - k + q]; };
  for (int q = 1; q <= kDegree; ++q)
    for (int i = k - q; i <= k; ++i)
      B[q][i - k + q] = safe_div(u - U[i], U[i + q] - U[i]) * value(q - 1, i) +
                        safe_div(U[i + q + 1] - u, U[i + q + 1] - U[i + 1]) * value(q - 1, i + 1);
  // Derivative of a degree-q basis function from degree q-1 ones (P&T Eq. 2.9).
  auto derivative = [&](int q, int i, auto&& lower) {
    return q *
           (safe_div(lower(i), U[i + q] - U[i]) - safe_div(lower(i + 1), U[i + q + 1] - U[i + 1]));
  };
  auto value1 = [&](int i) { return value(1, i); };
  auto value2 = [&](int i) { return value(2, i); };
  auto deriv2 = [&](int i) { return derivative(2, i, value1); };
  first = k - kDegree;
  for (int r = 0; r < 4; ++r) {
    const int i = first + r;
    N[r] = B[3][r];
    dN[r] = derivative(3, i, value2);
    ddN[r] = derivative(3, i, deriv2);
  }
}

CurvePoint BSpline2::eval(double u) const {
  const int spans = span_count();
  double base = 0;  // periodic: whole periods of u
  if (periodic_) {
    base = std::floor(u);
    u -= base;
  } else {
    u = std::clamp(u, 0.0, 1.0);
  }
  const Piece& piece = pieces_[std::min(static_cast<int>(u * spans), spans - 1)];
  const double s = u - piece.start;
  const auto& C = piece.coef;
  CurvePoint p;
  p.c = C.col(0) + s * (C.col(1) + s * (C.col(2) + s * C.col(3)));
  p.d1 = C.col(1) + s * (2.0 * C.col(2) + 3.0 * s * C.col(3));
  p.d2 = 2.0 * C.col(2) + 6.0 * s * C.col(3);
  if (periodic_) p.c += shift_ * base;
  return p;
}

CurvePoint BSpline2::eval_from_basis(double u) const {
  int first = 0;
  double N[4], dN[4], ddN[4];
  basis(u, first, N, dN, ddN);
  const int n = control_count();
  CurvePoint p{Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};
  for (int r = 0; r < 4; ++r) {
    const Vec2& P = control_[(first + r) % n];
    p.c += N[r] * P;
    p.d1 += dN[r] * P;
    p.d2 += ddN[r] * P;
  }
  if (periodic_) {  // c(u) = S(u) + shift·u with S periodic
    p.c += shift_ * u;
    p.d1 += shift_;
  }
  return p;
}

std::vector<double> chord_length_params(const std::vector<Vec2>& points, bool closed,
                                        const Vec2& period_shift) {
  const size_t m = points.size();
  std::vector<double> t(m, 0.0);
  for (size_t j = 1; j < m; ++j) t[j] = t[j - 1] + (points[j] - points[j - 1]).norm();
  double total = m ? t[m - 1] : 0.0;
  if (closed && m) total += (points[0] + period_shift - points[m - 1]).norm();
  if (!(total > 0.0)) throw Error("internal: cannot parameterise a curve of zero length");
  for (double& x : t) x /= total;
  return t;
}

BSpline2 fit_bspline(const std::vector<Vec2>& points, const std::vector<double>& params,
                     int control_count, double smoothing, bool periodic, const Vec2& period_shift) {
  const int n = control_count;
  if (n < kDegree + 1 || points.size() != params.size())
    throw Error("internal: bad B-spline fit request");
  // Basis functions only depend on the knots, so evaluate them with a dummy control polygon.
  const BSpline2 shape(std::vector<Vec2>(n, Vec2::Zero()), periodic);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);  // NᵀN + smoothing·DᵀD (P&T Eq. 9.66)
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 2);
  for (size_t j = 0; j < points.size(); ++j) {
    int first = 0;
    double N[4], dN[4], ddN[4];
    shape.basis(params[j], first, N, dN, ddN);
    const Vec2 q = periodic ? Vec2(points[j] - period_shift * params[j]) : points[j];
    for (int r = 0; r < 4; ++r) {
      const int a = (first + r) % n;
      rhs.row(a) += N[r] * q.transpose();
      for (int s = 0; s < 4; ++s) A(a, (first + s) % n) += N[r] * N[s];
    }
  }
  // Second-difference penalty on the control polygon (cyclic for periodic curves).
  const int lo = periodic ? 0 : 1, hi = periodic ? n : n - 1;
  for (int i = lo; i < hi; ++i) {
    const int idx[3] = {(i - 1 + n) % n, i, (i + 1) % n};
    const double c[3] = {1.0, -2.0, 1.0};
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s) A(idx[r], idx[s]) += smoothing * c[r] * c[s];
  }
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(A);
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-13))
    throw Error("internal: B-spline least-squares system is singular (too few data per span)");
  const Eigen::MatrixXd P = ldlt.solve(rhs);
  std::vector<Vec2> control(n);
  for (int i = 0; i < n; ++i) control[i] = P.row(i).transpose();
  return BSpline2(std::move(control), periodic, period_shift);
}

}  // namespace qd::approximate
