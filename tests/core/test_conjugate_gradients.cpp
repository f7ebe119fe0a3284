// Preconditioned conjugate gradients: the stopping rule means what it says, and CG gives up
// early when it could not make the tolerance in time.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "common/conjugate_gradients.h"

namespace qd {
namespace {

using namespace qd::common;

// The 1D Laplacian plus the identity: SPD, condition number about 4n²/π².
Eigen::MatrixXd laplacian_plus_identity(int n) {
  Eigen::MatrixXd M = 3.0 * Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i + 1 < n; ++i) M(i, i + 1) = M(i + 1, i) = -1.0;
  return M;
}

TEST(ConjugateGradients, AnExactPreconditionerSolvesInOneIteration) {
  const Eigen::MatrixXd M = laplacian_plus_identity(30);
  const Eigen::LDLT<Eigen::MatrixXd> exact(M);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(30, -1.0, 2.0);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(30);
  const CgOutcome out = conjugate_gradients(
      [&](const Eigen::VectorXd& p) -> Eigen::VectorXd { return M * p; },
      [&](const Eigen::VectorXd& r) -> Eigen::VectorXd { return exact.solve(r); }, b, x, 1e-10, 40);
  EXPECT_TRUE(out.converged);
  EXPECT_EQ(out.iterations, 1);
  EXPECT_LT((M * x - b).norm(), 1e-10 * b.norm());
}

TEST(ConjugateGradients, StopsAtTheToleranceOfTheCorrection) {
  const Eigen::MatrixXd M = laplacian_plus_identity(200);
  const Eigen::VectorXd x_star = Eigen::VectorXd::LinSpaced(200, 0.0, 1.0).array().sin();
  const Eigen::VectorXd b = M * x_star, x0 = Eigen::VectorXd::Constant(200, 0.5);
  const auto energy = [&](const Eigen::VectorXd& e) { return std::sqrt(e.dot(M * e)); };
  for (double tolerance : {1e-3, 1e-8}) {
    Eigen::VectorXd x = x0;
    const CgOutcome out = conjugate_gradients(
        [&](const Eigen::VectorXd& p) -> Eigen::VectorXd { return M * p; },
        [&](const Eigen::VectorXd& r) -> Eigen::VectorXd { return r / 3.0; }, b, x, tolerance, 400);
    EXPECT_TRUE(out.converged) << tolerance;
    // P = M's diagonal is within a factor 5 of M, so the error is within √5·tolerance of the
    // correction's size in M's energy norm.
    EXPECT_LT(energy(x - x_star), 3.0 * tolerance * energy(x_star - x0)) << tolerance;
    EXPECT_GT(energy(x - x_star), 0.0);
  }
}

// A warm start near the solution saves iterations and still meets the tolerance of the
// correction from the reference point; a guess worse than the reference is not taken.
TEST(ConjugateGradients, AWarmStartSavesIterationsToTheSameTolerance) {
  const Eigen::MatrixXd M = laplacian_plus_identity(200);
  const Eigen::VectorXd x_star = Eigen::VectorXd::LinSpaced(200, 0.0, 1.0).array().sin();
  const Eigen::VectorXd b = M * x_star, x0 = Eigen::VectorXd::Constant(200, 0.5);
  const auto energy = [&](const Eigen::VectorXd& e) { return std::sqrt(e.dot(M * e)); };
  const auto solve = [&](const Eigen::VectorXd* guess, Eigen::VectorXd& x) {
    x = x0;
    return conjugate_gradients([&](const Eigen::VectorXd& p) -> Eigen::VectorXd { return M * p; },
                               [&](const Eigen::VectorXd& r) -> Eigen::VectorXd { return r / 3.0; },
                               b, x, 1e-6, 400, guess);
  };
  Eigen::VectorXd cold, warm, ignored;
  const CgOutcome from_reference = solve(nullptr, cold);
  const Eigen::VectorXd near = x_star + 1e-4 * Eigen::VectorXd::LinSpaced(200, -1.0, 1.0);
  const CgOutcome from_guess = solve(&near, warm);
  EXPECT_TRUE(from_guess.converged);
  EXPECT_LE(3 * from_guess.iterations, 2 * from_reference.iterations);
  EXPECT_LT(energy(warm - x_star), 3.0 * 1e-6 * energy(x_star - x0));
  const Eigen::VectorXd far = x_star + 10.0 * (x_star - x0);
  const CgOutcome from_far = solve(&far, ignored);
  EXPECT_EQ(from_far.iterations, from_reference.iterations);
  EXPECT_EQ(ignored, cold);
}

TEST(ConjugateGradients, GivesUpEarlyWhenItCannotMakeTheToleranceInTime) {
  const int n = 400;  // eigenvalues spread evenly in log scale over 1 .. 1e6
  const Eigen::MatrixXd M = Eigen::VectorXd::LinSpaced(n, 0.0, 6.0)
                                .unaryExpr([](double e) { return std::pow(10.0, e); })
                                .asDiagonal();
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  const CgOutcome out = conjugate_gradients(
      [&](const Eigen::VectorXd& p) -> Eigen::VectorXd { return M * p; },
      [](const Eigen::VectorXd& r) -> Eigen::VectorXd { return r; }, b, x, 1e-10, 40);
  EXPECT_FALSE(out.converged);
  EXPECT_GE(out.iterations, kCgPatience);
  EXPECT_LT(out.iterations, 40);
}

}  // namespace
}  // namespace qd
