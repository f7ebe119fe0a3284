// Preconditioned conjugate gradients for a symmetric positive definite system (issue 5: the
// coupled system of Eq. 17 solved without factorising it).
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace qd::common {

constexpr int kCgPatience = 10;

struct CgOutcome {
  int iterations = 0;
  bool converged = false;
};

// Solves M x = b from the reference point in x. multiply(p) returns M p, precondition(r) returns
// P⁻¹ r for an SPD P ≈ M. Stops when √(rᵀP⁻¹r) has fallen to `tolerance` times its value at the
// reference: with P ≈ M that is the error of the correction in the energy norm, relative to the
// correction. The iterations start from `guess` (e.g. the solution of a similar system just
// solved) when its residual is the smaller: a warm start to the same tolerance, for one more
// product with M, and one more preconditioning when the guess is taken. Gives up (not
// converged) after max_iterations, or earlier, from kCgPatience iterations on, once the fall so
// far is slower than the steady rate that would reach the tolerance in time.
template <typename Multiply, typename Precondition>
CgOutcome conjugate_gradients(const Multiply& multiply, const Precondition& precondition,
                              const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance,
                              int max_iterations, const Eigen::VectorXd* guess = nullptr) {
  CgOutcome out;
  Eigen::VectorXd r = b - multiply(x);
  double reference = -1;  // rᵀP⁻¹r at the reference point, when the iterations start elsewhere
  if (guess && guess->size() == x.size()) {
    Eigen::VectorXd r_guess = b - multiply(*guess);
    if (r_guess.squaredNorm() < r.squaredNorm()) {
      reference = r.dot(precondition(r));
      x = *guess;
      r = std::move(r_guess);
    }
  }
  Eigen::VectorXd z = precondition(r);
  double rz = r.dot(z);
  const double start = rz, stop = tolerance * tolerance * (reference >= 0 ? reference : rz);
  const auto on_time = [&] {  // √(rz/start) ≤ tolerance^(iterations/max_iterations)
    return out.iterations < kCgPatience ||
           rz <= start * std::pow(tolerance * tolerance,
                                  static_cast<double>(out.iterations) / max_iterations);
  };
  Eigen::VectorXd p = z;
  while (rz > stop && out.iterations < max_iterations && on_time()) {
    const Eigen::VectorXd q = multiply(p);
    const double step = rz / p.dot(q);
    x += step * p;
    r -= step * q;
    z = precondition(r);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
    ++out.iterations;
  }
  out.converged = rz <= stop;
  return out;
}

}  // namespace qd::common
