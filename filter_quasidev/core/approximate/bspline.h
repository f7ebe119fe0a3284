// Least-squares cubic B-spline curves in the plane (Piegl & Tiller, The NURBS Book, ch. 9.4.1),
// used for the skeleton curve c_2D of Step 1 (§5.1).
//   chord_length_params: data points -> parameters in [0, 1) (closed) or [0, 1] (open).
//   fit_bspline:         data points + parameters -> open-clamped or periodic cubic spline.
//   BSpline2::eval:      parameter -> point and its first two derivatives.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace qd::approximate {

using Vec2 = Eigen::Vector2d;

// Value and derivatives of a curve at one parameter.
struct CurvePoint {
  Vec2 c, d1, d2;
};

class BSpline2 {
 public:
  // Open: clamped cubic with uniform interior knots on [0, 1].
  // Periodic: uniform cubic on [0, 1) that repeats with period 1 up to the translation
  // `period_shift` (c(u + 1) = c(u) + period_shift); shift 0 is a plain closed curve, a shift of
  // (±2π, 0) is a curve that winds once around the θ-periodic domain of Eq. 9.
  BSpline2(std::vector<Vec2> control, bool periodic, const Vec2& period_shift = Vec2::Zero());

  CurvePoint eval(double u) const;  // u outside the domain: clamped (open) or wrapped (periodic)
  bool periodic() const { return periodic_; }
  int control_count() const { return static_cast<int>(control_.size()); }
  const std::vector<Vec2>& control() const { return control_; }

  // Basis functions of the curve at u: first control index and the 4 non-zero weights
  // (indices wrap modulo the control count for periodic curves).
  void basis(double u, int& first, double N[4], double dN[4], double ddN[4]) const;

  int span_count() const { return static_cast<int>(pieces_.size()); }

 private:
  // One polynomial piece: c(u) = Σ_k coef.col(k)·(u − start)^k on its knot span (the curve
  // converted to power form once, so eval costs a few multiply-adds).
  struct Piece {
    double start;
    Eigen::Matrix<double, 2, 4> coef;
  };
  CurvePoint eval_from_basis(double u) const;

  std::vector<Vec2> control_;
  bool periodic_;
  Vec2 shift_;
  std::vector<double> knots_;  // open curves only: clamped knot vector
  std::vector<Piece> pieces_;  // uniform spans of [0, 1]
};

// Normalised cumulative chord length of the points (closed: the closing chord counts too,
// so the parameters lie in [0, 1) and the last point is not at 1).
std::vector<double> chord_length_params(const std::vector<Vec2>& points, bool closed,
                                        const Vec2& period_shift = Vec2::Zero());

// Least-squares fit with `control_count` control points (>= 4) minimising
//   Σ_j |c(u_j) − q_j|² + smoothing · Σ_i |P_{i−1} − 2 P_i + P_{i+1}|²   (P&T Eq. 9.63 + penalty).
// smoothing = 0 gives the plain least-squares fit (then enough data must lie in every span).
// Throws qd::common::Error when the system is singular.
BSpline2 fit_bspline(const std::vector<Vec2>& points, const std::vector<double>& params,
                     int control_count, double smoothing, bool periodic,
                     const Vec2& period_shift = Vec2::Zero());

}  // namespace qd::approximate
