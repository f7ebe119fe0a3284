// Quasi-definite factors of one pattern sharing its supernodal analysis: the first factor's
// analysis serves the second, whose values differ, and the second solves as a factor with an
// analysis of its own does.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "common/quasi_definite_factor.h"
#include "solver_matrices.h"

namespace qd {
namespace {

using namespace qd::common;

TEST(SharedAnalysis, ASharedAnalysisSolvesAsAFreshOne) {
  const Eigen::SparseMatrix<double> K1 = test::random_quasi_definite(300, 90, 3, 5);
  Eigen::SparseMatrix<double> K2 = K1;  // same pattern, other values: the H part shifted
  for (int j = 0; j < 300; ++j) K2.coeffRef(j, j) += 1.0;
  const Eigen::VectorXd b = Eigen::VectorXd::Random(K1.rows());

  const auto shared = std::make_shared<SharedAnalysis>();
  QuasiDefiniteFactor first(SolverKind::Auto, shared), second(SolverKind::Auto, shared);
  first.factorize(K1);
  ASSERT_NE(shared->supernodal, nullptr) << "the first factorisation analyses";
  const auto analysis = shared->supernodal;
  second.factorize(K2);
  EXPECT_EQ(shared->supernodal, analysis) << "the second takes the first's analysis";
  EXPECT_EQ(second.backend(), FactorBackend::SupernodalLdlt);

  QuasiDefiniteFactor fresh(SolverKind::Auto);
  fresh.factorize(K2);
  const Eigen::VectorXd x = second.solve(b), expected = fresh.solve(b);
  EXPECT_LT((x - expected).norm(), 1e-12 * expected.norm());
  EXPECT_LT((b - K2.selfadjointView<Eigen::Lower>() * x).norm(), 1e-9 * b.norm());
  // The first factor still holds K1's values.
  const Eigen::VectorXd x1 = first.solve(b);
  EXPECT_LT((b - K1.selfadjointView<Eigen::Lower>() * x1).norm(), 1e-9 * b.norm());
}

}  // namespace
}  // namespace qd
