#include "vertex_order.h"

#include <numeric>

#include "block_pattern.h"
#include "error.h"
#ifdef QD_WITH_CHOLMOD
#include <cholmod.h>
#else
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#endif

namespace qd {
namespace {

#ifdef QD_WITH_CHOLMOD
// perm[k]: the node eliminated k-th, as CHOLMOD chooses it.
void elimination_order(int nodes, const BlockPattern& lower, std::vector<int>& perm) {
  cholmod_common common;
  cholmod_start(&common);
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_AMD;
  common.supernodal = CHOLMOD_SIMPLICIAL;
  cholmod_sparse* pattern = cholmod_allocate_sparse(static_cast<size_t>(nodes), static_cast<size_t>(nodes),
                                                    lower.block_row.size() + static_cast<size_t>(nodes), 1, 1, -1,
                                                    CHOLMOD_PATTERN, &common);
  cholmod_factor* symbolic = nullptr;
  if (pattern) {
    int* p = static_cast<int*>(pattern->p);
    int* i = static_cast<int*>(pattern->i);
    int at = 0;
    for (int c = 0; c < nodes; ++c) {  // the diagonal, then the neighbours below it
      p[c] = at;
      i[at++] = c;
      for (int s = lower.begin(c); s < lower.end(c); ++s) i[at++] = lower.row(s);
    }
    p[nodes] = at;
    symbolic = cholmod_analyze(pattern, &common);
  }
  if (symbolic) {
    const int* order = static_cast<const int*>(symbolic->Perm);
    perm.assign(order, order + nodes);
  }
  const bool ok = symbolic != nullptr;
  cholmod_free_factor(&symbolic, &common);
  cholmod_free_sparse(&pattern, &common);
  cholmod_finish(&common);
  if (!ok) throw Error("out of memory while ordering the deformation system");
}
#else
// perm[k]: the node eliminated k-th by Eigen's minimum degree (AMD).
void elimination_order(int nodes, const BlockPattern& lower, std::vector<int>& perm) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(lower.block_row.size() + static_cast<size_t>(nodes));
  for (int c = 0; c < nodes; ++c) {
    entries.emplace_back(c, c, 1.0);
    for (int s = lower.begin(c); s < lower.end(c); ++s) entries.emplace_back(lower.row(s), c, 1.0);
  }
  Eigen::SparseMatrix<double> graph(nodes, nodes);
  graph.setFromTriplets(entries.begin(), entries.end());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  Eigen::AMDOrdering<int>()(graph.selfadjointView<Eigen::Lower>(), order);
  perm.assign(order.indices().data(), order.indices().data() + nodes);
}
#endif

}  // namespace

std::vector<int> fill_reducing_rank(int nodes, const std::vector<std::pair<int, int>>& edges) {
  std::vector<int> rank(static_cast<size_t>(nodes));
  std::iota(rank.begin(), rank.end(), 0);
  if (nodes < 2) return rank;
  std::vector<int> perm;
  elimination_order(nodes, lower_pattern(nodes, edges), perm);
  for (int k = 0; k < nodes; ++k) rank[static_cast<size_t>(perm[static_cast<size_t>(k)])] = k;
  return rank;
}

}  // namespace qd
