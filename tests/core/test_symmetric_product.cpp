// The product of a symmetric matrix stored as its lower triangle: the same product as Eigen's,
// and the same result on any number of threads, on both sides of the split.
#include <gtest/gtest.h>

#include <Eigen/SparseCore>
#include <random>
#include <vector>

#include "common/symmetric_product.h"

namespace qd {
namespace {

using namespace qd::common;

// A random lower triangle of n columns with about `per_column` entries each below the diagonal,
// a diagonal in most columns, and every 97th column empty.
Eigen::SparseMatrix<double> random_lower(int n, int per_column, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < n; ++j) {
    if (j % 97 == 0) continue;
    if (j % 5 != 0) entries.emplace_back(j, j, 4.0 + value(random));
    std::uniform_int_distribution<int> below(j + 1, n - 1);
    for (int k = 0; k < per_column && j + 1 < n; ++k)
      entries.emplace_back(below(random), j, value(random));
  }
  Eigen::SparseMatrix<double> lower(n, n);
  lower.setFromTriplets(entries.begin(), entries.end());
  return lower;
}

Eigen::VectorXd random_vector(int n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = value(random);
  return x;
}

TEST(SymmetricProduct, SplitProductIsTheSymmetricProductOnAnyThreadCount) {
  const int n = 150000;
  const Eigen::SparseMatrix<double> lower = random_lower(n, 8, 1);
  ASSERT_GE(lower.nonZeros(), kSplitProductFromEntries);  // the split is taken
  const Eigen::VectorXd x = random_vector(n, 2);
  const Eigen::VectorXd reference = lower.selfadjointView<Eigen::Lower>() * x;
  const Eigen::VectorXd one = symmetric_product(lower, x, 1);
  const Eigen::VectorXd two = symmetric_product(lower, x, 2);
  EXPECT_LT((one - reference).cwiseAbs().maxCoeff(), 1e-12 * reference.cwiseAbs().maxCoeff());
  // The halves and the order of their sum do not depend on the threads: the same bits.
  EXPECT_EQ((one - two).cwiseAbs().maxCoeff(), 0.0);
}

TEST(SymmetricProduct, AnUncompressedMatrixGivesTheSameProduct) {
  const int n = 150000;
  Eigen::SparseMatrix<double> lower = random_lower(n, 8, 5);
  const Eigen::VectorXd x = random_vector(n, 6);
  const Eigen::VectorXd reference = lower.selfadjointView<Eigen::Lower>() * x;
  lower.uncompress();
  lower.reserve(Eigen::VectorXi::Constant(n, 2));  // room between the columns
  ASSERT_FALSE(lower.isCompressed());
  EXPECT_LT((symmetric_product(lower, x, 2) - reference).cwiseAbs().maxCoeff(),
            1e-12 * reference.cwiseAbs().maxCoeff());
}

TEST(SymmetricProduct, SmallMatricesTakeOnePass) {
  const int n = 2000;
  const Eigen::SparseMatrix<double> lower = random_lower(n, 4, 3);
  ASSERT_LT(lower.nonZeros(), kSplitProductFromEntries);
  const Eigen::VectorXd x = random_vector(n, 4);
  const Eigen::VectorXd reference = lower.selfadjointView<Eigen::Lower>() * x;
  EXPECT_LT((symmetric_product(lower, x, 2) - reference).cwiseAbs().maxCoeff(),
            1e-12 * reference.cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace qd
