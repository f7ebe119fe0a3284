#include "common/supernodal_backend.h"

#include "common/quasi_definite_ldlt.h"

namespace qd::common {
namespace {

struct SupernodalBackend : SparseFactor::Backend {
  std::shared_ptr<SharedAnalysis> shared;
  bool positive;
  std::unique_ptr<QuasiDefiniteLdlt> ldlt;
  SupernodalBackend(std::shared_ptr<SharedAnalysis> s, bool p)
      : shared(std::move(s)), positive(p) {}
  bool analyse_and_factorize(const Eigen::SparseMatrix<double>& lower, bool analyse) override {
    if (analyse) {
      const std::lock_guard<std::mutex> lock(shared->mutex);
      if (!shared->supernodal) shared->supernodal = QuasiDefiniteLdlt::analyse(lower);
      ldlt = std::make_unique<QuasiDefiniteLdlt>(shared->supernodal);
      flops = shared->supernodal->flops;
      entries = shared->supernodal->entries;
    }
    return ldlt->factorize(lower) && (!positive || ldlt->pivots_positive());
  }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const override { return ldlt->solve(b); }
};

}  // namespace

std::unique_ptr<SparseFactor::Backend> supernodal_backend(std::shared_ptr<SharedAnalysis> shared,
                                                          bool positive) {
  return std::make_unique<SupernodalBackend>(std::move(shared), positive);
}

}  // namespace qd::common
