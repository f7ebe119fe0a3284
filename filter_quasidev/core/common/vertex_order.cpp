#include "common/vertex_order.h"

#include <numeric>

#include "common/block_pattern.h"
#include "common/error.h"
#ifdef QD_WITH_CHOLMOD
#include <Eigen/CholmodSupport>
#else
#include <Eigen/OrderingMethods>
#endif

namespace qd::common {
namespace {

#ifdef QD_WITH_CHOLMOD
// perm[k]: the node eliminated k-th, as CHOLMOD chooses it. graph: lower triangle with diagonal.
void elimination_order(const Eigen::SparseMatrix<double>& graph, std::vector<int>& perm) {
  cholmod_common common;
  cholmod_start(&common);
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_AMD;
  common.supernodal = CHOLMOD_SIMPLICIAL;
  cholmod_sparse view = Eigen::viewAsCholmod(graph.selfadjointView<Eigen::Lower>());
  cholmod_factor* symbolic = cholmod_analyze(&view, &common);
  if (symbolic) {
    const int* order = static_cast<const int*>(symbolic->Perm);
    perm.assign(order, order + graph.rows());
  }
  const bool ok = symbolic != nullptr;
  cholmod_free_factor(&symbolic, &common);
  cholmod_finish(&common);
  if (!ok) throw Error("out of memory while ordering the deformation system");
}
#else
// perm[k]: the node eliminated k-th by Eigen's minimum degree (AMD). graph: lower triangle.
void elimination_order(const Eigen::SparseMatrix<double>& graph, std::vector<int>& perm) {
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  Eigen::AMDOrdering<int>()(graph.selfadjointView<Eigen::Lower>(), order);
  perm.assign(order.indices().data(), order.indices().data() + graph.rows());
}
#endif

}  // namespace

std::vector<int> fill_reducing_rank(int nodes, const std::vector<std::pair<int, int>>& edges) {
  std::vector<int> rank(static_cast<size_t>(nodes));
  std::iota(rank.begin(), rank.end(), 0);
  if (nodes < 2) return rank;
  std::vector<int> perm;
  elimination_order(scalar_lower(lower_pattern(nodes, edges)), perm);
  for (int k = 0; k < nodes; ++k) rank[static_cast<size_t>(perm[static_cast<size_t>(k)])] = k;
  return rank;
}

}  // namespace qd::common
