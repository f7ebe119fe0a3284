// The positive-definite and quasi-definite factors: every back end solves small systems to
// tolerance, a matrix of the wrong class is reported as a failure, and a back end that cannot
// factorise the matrix's class is substituted openly.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "common/error.h"
#include "common/positive_definite_factor.h"
#include "common/quasi_definite_factor.h"
#include "solver_matrices.h"

namespace qd {
namespace {

using namespace qd::common;

constexpr SolverKind kEverySolver[] = {SolverKind::Auto, SolverKind::Cholmod, SolverKind::EigenLLT,
                                       SolverKind::EigenLDLT};
constexpr Solves kEverySolves[] = {Solves::Few, Solves::AtOnce, Solves::Many};

double relative_residual(const Eigen::SparseMatrix<double>& lower, const Eigen::MatrixXd& x,
                         const Eigen::MatrixXd& b) {
  return (b - lower.selfadjointView<Eigen::Lower>() * x).norm() / b.norm();
}

TEST(PositiveDefiniteFactor, EveryBackEndSolvesAnSpdSystem) {
  // 1,600 unknowns: Auto takes a supernodal factor (kCholmodFromUnknowns)
  const Eigen::SparseMatrix<double> L =
      test::laplacian_lower(40 * 40, test::grid_edges(40, 40), 0.1);
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(L.rows(), 2);
  for (const SolverKind kind : kEverySolver)
    for (const Solves solves : kEverySolves) {
      PositiveDefiniteFactor factor(kind, solves);
      factor.factorize(L);
      factor.factorize(L);  // again, on the analysis of the first
      EXPECT_EQ(factor.factorizations(), 2);
      EXPECT_FALSE(factor.substituted());
      EXPECT_LT(relative_residual(L, factor.solve(b), b), 1e-10);
    }
}

// A matrix given with both triangles is read by its lower one, by every back end (the flattening
// passes its Laplacians so).
TEST(PositiveDefiniteFactor, EveryBackEndReadsTheLowerTriangle) {
  const Eigen::SparseMatrix<double> L =
      test::laplacian_lower(40 * 40, test::grid_edges(40, 40), 0.1);
  Eigen::SparseMatrix<double> both(L.rows(), L.cols());
  both = L.selfadjointView<Eigen::Lower>();
  ASSERT_EQ(both.nonZeros(), 2 * L.nonZeros() - L.rows());
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(L.rows(), 2);
  for (const SolverKind kind : kEverySolver)
    for (const Solves solves : kEverySolves) {
      PositiveDefiniteFactor factor(kind, solves);
      factor.factorize(both);
      EXPECT_LT(relative_residual(L, factor.solve(b), b), 1e-10) << static_cast<int>(kind);
    }
}

// From its threshold Auto takes a supernodal factor: the LDLᵀ on CHOLMOD's analysis, or CHOLMOD's
// LLᵀ for a factor that serves many solves one after another.
TEST(PositiveDefiniteFactor, AutoTakesASupernodalFactorFromItsThreshold) {
  PositiveDefiniteFactor small(SolverKind::Auto), large(SolverKind::Auto),
      at_once(SolverKind::Auto, Solves::AtOnce), many(SolverKind::Auto, Solves::Many);
  small.factorize(test::laplacian_lower(100, test::path_edges(100), 1.0));
  const int n = static_cast<int>(kCholmodFromUnknowns);
  for (PositiveDefiniteFactor* f : {&large, &at_once, &many})
    f->factorize(test::laplacian_lower(n, test::path_edges(n), 1.0));
  EXPECT_EQ(small.backend(), FactorBackend::EigenLdlt);
  EXPECT_EQ(large.backend(), FactorBackend::SupernodalLdlt);
  EXPECT_EQ(at_once.backend(), FactorBackend::SupernodalLdlt);
  EXPECT_EQ(many.backend(), FactorBackend::CholmodLlt);
}

TEST(PositiveDefiniteFactor, ReportsAnIndefiniteMatrix) {
  // Laplacians shifted by −0.5: their smallest eigenvalue is −0.5 (and no pivot vanishes);
  // the larger one goes to the supernodal back ends.
  for (const int n : {40, static_cast<int>(kCholmodFromUnknowns)}) {
    const Eigen::SparseMatrix<double> L = test::laplacian_lower(n, test::path_edges(n), -0.5);
    for (const SolverKind kind : kEverySolver)
      for (const Solves solves : kEverySolves) {
        PositiveDefiniteFactor factor(kind, solves);
        EXPECT_THROW(factor.factorize(L), Error) << n << " " << static_cast<int>(kind);
      }
  }
}

// The counts of a tridiagonal matrix's factor: columns of 2 entries but the last, so 2n − 1
// entries and 4 (n − 1) + 1 flops per factorisation, by every back end.
TEST(PositiveDefiniteFactor, CountsTheFlopsAndEntriesOfItsFactor) {
  const int n = 3000;  // above kCholmodFromUnknowns: Auto takes a supernodal factor
  const Eigen::SparseMatrix<double> L = test::laplacian_lower(n, test::path_edges(n), 1.0);
  for (const SolverKind kind : kEverySolver)
    for (const Solves solves : kEverySolves) {
      PositiveDefiniteFactor factor(kind, solves);
      EXPECT_EQ(factor.flops(), 0.0);
      factor.factorize(L);
      factor.factorize(L);
      EXPECT_EQ(factor.flops(), 2.0 * (4.0 * (n - 1) + 1)) << static_cast<int>(kind);
      EXPECT_EQ(factor.entries(), 2.0 * n - 1) << static_cast<int>(kind);
    }
}

// On a grid, whose factor fills in, the back ends count the same flops and entries, CHOLMOD's
// analysis and Eigen's factor alike, for both classes of matrix.
TEST(SparseFactor, EveryBackEndCountsTheSameFlopsAndEntries) {
  const Eigen::SparseMatrix<double> L =
      test::laplacian_lower(30 * 20, test::grid_edges(30, 20), 0.1);
  const Eigen::SparseMatrix<double> K = test::random_quasi_definite(60, 20, 2, 3);
  for (const SolverKind kind : kEverySolver) {
    PositiveDefiniteFactor spd(kind), reference(SolverKind::EigenLLT);
    QuasiDefiniteFactor quasi(kind), quasi_reference(SolverKind::EigenLDLT);
    spd.factorize(L), reference.factorize(L), quasi.factorize(K), quasi_reference.factorize(K);
    EXPECT_GT(reference.flops(), 4.0 * 30 * 20);  // more than without fill
    EXPECT_EQ(spd.flops(), reference.flops()) << static_cast<int>(kind);
    EXPECT_EQ(quasi.flops(), quasi_reference.flops()) << static_cast<int>(kind);
    EXPECT_EQ(spd.entries(), reference.entries()) << static_cast<int>(kind);
    EXPECT_EQ(quasi.entries(), quasi_reference.entries()) << static_cast<int>(kind);
  }
}

TEST(QuasiDefiniteFactor, EveryBackEndSolvesAQuasiDefiniteSystem) {
  const Eigen::SparseMatrix<double> K = test::random_quasi_definite(60, 20, 2, 3);
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(K.rows(), 3);
  for (const SolverKind kind : kEverySolver) {
    QuasiDefiniteFactor factor(kind);
    factor.factorize(K);
    factor.factorize(K);
    EXPECT_EQ(factor.factorizations(), 2);
    EXPECT_LT(relative_residual(K, factor.solve(b), b), 1e-10);
  }
}

TEST(QuasiDefiniteFactor, SubstitutesLdltForLltOpenly) {
  const Eigen::SparseMatrix<double> K = test::random_quasi_definite(20, 5, 2, 4);
  QuasiDefiniteFactor llt(SolverKind::EigenLLT), cholmod(SolverKind::Cholmod);
  llt.factorize(K);
  cholmod.factorize(K);
  EXPECT_TRUE(llt.substituted());
  EXPECT_EQ(llt.backend(), FactorBackend::EigenLdlt);
  EXPECT_FALSE(cholmod.substituted());
  EXPECT_EQ(cholmod.backend(), FactorBackend::SupernodalLdlt);
}

TEST(QuasiDefiniteFactor, ReportsAVanishingPivot) {
  Eigen::SparseMatrix<double> K(3, 3);
  K.insert(0, 0) = 1, K.insert(1, 0) = 1, K.insert(1, 1) = 1, K.insert(2, 2) = -1;
  K.makeCompressed();
  for (const SolverKind kind : kEverySolver) {
    QuasiDefiniteFactor factor(kind);
    EXPECT_THROW(factor.factorize(K), Error);
  }
}

}  // namespace
}  // namespace qd
