// Preconditioned conjugate gradients for a symmetric positive definite system (issue 5: the
// coupled system of Eq. 17 solved without factorising it).
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace qd {

constexpr int kCgPatience = 10;

struct CgOutcome {
  int iterations = 0;
  bool converged = false;
};

// Solves M x = b from the start guess in x. multiply(p) returns M p, precondition(r) returns
// P⁻¹ r for an SPD P ≈ M. Stops when √(rᵀP⁻¹r) has fallen to `tolerance` times its start value:
// with P ≈ M that is the error of the correction in the energy norm, relative to the correction.
// Gives up (not converged) after max_iterations, or earlier, from kCgPatience iterations on,
// once the fall so far is slower than the steady rate that would reach the tolerance in time.
template <typename Multiply, typename Precondition>
CgOutcome conjugate_gradients(const Multiply& multiply, const Precondition& precondition,
                              const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance,
                              int max_iterations) {
  CgOutcome out;
  Eigen::VectorXd r = b - multiply(x);
  Eigen::VectorXd z = precondition(r);
  double rz = r.dot(z);
  const double start = rz, stop = tolerance * tolerance * rz;
  const auto on_time = [&] {  // √(rz/start) ≤ tolerance^(iterations/max_iterations)
    return out.iterations < kCgPatience ||
           rz <= start * std::pow(tolerance * tolerance, static_cast<double>(out.iterations) / max_iterations);
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

}  // namespace qd
