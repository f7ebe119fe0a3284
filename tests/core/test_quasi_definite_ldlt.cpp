// QuasiDefiniteLdlt against Eigen's SimplicialLDLT on random quasi-definite systems whose
// supernodes are narrower and wider than its blocking thresholds, and its report of a
// vanishing pivot.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <ostream>
#include <random>

#include "common/quasi_definite_ldlt.h"
#include "solver_matrices.h"

namespace qd {
namespace {

using namespace qd::common;

Eigen::VectorXd random_vector(Eigen::Index n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) b[i] = value(rng);
  return b;
}

struct Size {
  int a, c, per_column;
  int widest_at_least;  // the widest supernode the system must have, to reach a blocked path
};

void PrintTo(const Size& s, std::ostream* out) { *out << s.a << "+" << s.c << " unknowns"; }

class RandomQuasiDefinite : public testing::TestWithParam<Size> {};

TEST_P(RandomQuasiDefinite, SolvesAsSimplicialLdlt) {
  const Size size = GetParam();
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const Eigen::SparseMatrix<double> K =
        test::random_quasi_definite(size.a, size.c, size.per_column, seed);
    QuasiDefiniteLdlt ldlt(K);
    EXPECT_GE(ldlt.widest_supernode(), size.widest_at_least);
    ASSERT_TRUE(ldlt.factorize(K));
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> reference(K);
    ASSERT_EQ(reference.info(), Eigen::Success);
    const Eigen::VectorXd b = random_vector(K.rows(), seed);
    const Eigen::VectorXd x = ldlt.solve(b), expected = reference.solve(b);
    EXPECT_LT((x - expected).norm(), 1e-9 * expected.norm()) << "seed " << seed;
    const Eigen::VectorXd residual = b - K.selfadjointView<Eigen::Lower>() * x;
    EXPECT_LT(residual.norm(), 1e-9 * b.norm()) << "seed " << seed;
  }
}

// Natural order on a random graph fills in: the sparser and smaller systems keep supernodes
// below kUnblocked, the larger ones end in a dense block wider than kUnblocked and then than
// kUpdateColumns, so the recursive dense LDLᵀ and the split updates both run.
INSTANTIATE_TEST_SUITE_P(Sizes, RandomQuasiDefinite,
                         testing::Values(Size{12, 6, 1, 1}, Size{24, 8, 2, 1},
                                         Size{40, 12, 2, QuasiDefiniteLdlt::kUnblocked + 1},
                                         Size{200, 60, 3, QuasiDefiniteLdlt::kUnblocked + 1},
                                         Size{500, 150, 3, QuasiDefiniteLdlt::kUpdateColumns + 1},
                                         Size{900, 300, 2, QuasiDefiniteLdlt::kUpdateColumns + 1}));

// [[1, 1], [1, 1]]: the second pivot is 1 − 1 = 0.
TEST(QuasiDefiniteLdlt, ReportsAZeroPivot) {
  Eigen::SparseMatrix<double> K(2, 2);
  K.insert(0, 0) = 1, K.insert(1, 0) = 1, K.insert(1, 1) = 1;
  K.makeCompressed();
  QuasiDefiniteLdlt ldlt(K);
  EXPECT_FALSE(ldlt.factorize(K));
}

// A pivot of 1e-17 relative to its row rounds to zero: a failure, not an infinite solution.
TEST(QuasiDefiniteLdlt, ReportsAPivotLostToRounding) {
  Eigen::SparseMatrix<double> K(2, 2);
  K.insert(0, 0) = 1, K.insert(1, 0) = 1, K.insert(1, 1) = 1 + 1e-17;
  K.makeCompressed();
  QuasiDefiniteLdlt ldlt(K);
  EXPECT_FALSE(ldlt.factorize(K));
}

// The all-ones matrix of rank one, wider than kUnblocked: its second pivot vanishes inside the
// recursive dense factorisation.
TEST(QuasiDefiniteLdlt, ReportsAZeroPivotInABlockedSupernode) {
  const int n = 2 * QuasiDefiniteLdlt::kUnblocked + 8;
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j)
    for (int i = j; i < n; ++i) t.emplace_back(i, j, 1.0);
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  QuasiDefiniteLdlt ldlt(K);
  ASSERT_GT(ldlt.widest_supernode(), QuasiDefiniteLdlt::kUnblocked);
  EXPECT_FALSE(ldlt.factorize(K));
}

// A factorisation that failed leaves the next one, of good values, unharmed.
TEST(QuasiDefiniteLdlt, RefactorisesAfterAFailure) {
  Eigen::SparseMatrix<double> K = test::random_quasi_definite(30, 10, 2, 7);
  QuasiDefiniteLdlt ldlt(K);
  Eigen::SparseMatrix<double> zero = K;
  zero.coeffs().setZero();
  EXPECT_FALSE(ldlt.factorize(zero));
  ASSERT_TRUE(ldlt.factorize(K));
  const Eigen::VectorXd b = random_vector(K.rows(), 7);
  const Eigen::VectorXd residual = b - K.selfadjointView<Eigen::Lower>() * ldlt.solve(b);
  EXPECT_LT(residual.norm(), 1e-9 * b.norm());
}

}  // namespace
}  // namespace qd
