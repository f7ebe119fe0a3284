#include "common/vertex_order.h"

#include <future>
#include <mutex>
#include <numeric>

#include "common/block_pattern.h"
#include "common/coordinate_dissection.h"
#include "common/error.h"
#ifdef QD_WITH_CHOLMOD
#include <Eigen/CholmodSupport>
#else
#include <Eigen/OrderingMethods>
#endif

namespace qd::common {
namespace {

#ifdef QD_WITH_CHOLMOD
// perm[k]: the node eliminated k-th, as CHOLMOD chooses it (of several orders, the one whose
// factor has fewest entries). graph: lower triangle with diagonal.
void elimination_order(const Eigen::SparseMatrix<double>& graph, FillOrder order,
                       std::vector<int>& perm) {
  cholmod_common common;
  cholmod_start(&common);
  common.nmethods = order == FillOrder::LeastFill ? 2 : 1;
  common.method[0].ordering = CHOLMOD_AMD;
  common.method[1].ordering = CHOLMOD_METIS;
  common.supernodal = CHOLMOD_SIMPLICIAL;
  cholmod_sparse view = Eigen::viewAsCholmod(graph.selfadjointView<Eigen::Lower>());
  // METIS draws from one random generator per process: two orders computed at once on two
  // threads would each depend on the other's draws, and the result on the thread count.
  static std::mutex metis;
  std::unique_lock<std::mutex> one_at_a_time(metis, std::defer_lock);
  if (order == FillOrder::LeastFill) one_at_a_time.lock();
  cholmod_factor* symbolic = cholmod_analyze(&view, &common);
  if (symbolic) {
    const int* chosen = static_cast<const int*>(symbolic->Perm);
    perm.assign(chosen, chosen + graph.rows());
  }
  const bool ok = symbolic != nullptr;
  cholmod_free_factor(&symbolic, &common);
  cholmod_finish(&common);
  if (!ok) throw Error("out of memory while ordering the deformation system");
}

// An order of `graph` and its factor's entries: AMD's (given null) or the given one.
struct CountedOrder {
  std::vector<int> perm;
  double entries = 0;
};
CountedOrder counted_order(const Eigen::SparseMatrix<double>& graph, int* given) {
  cholmod_common common;
  cholmod_start(&common);
  common.nmethods = 1;
  common.method[0].ordering = given ? CHOLMOD_GIVEN : CHOLMOD_AMD;
  common.supernodal = CHOLMOD_SIMPLICIAL;
  cholmod_sparse view = Eigen::viewAsCholmod(graph.selfadjointView<Eigen::Lower>());
  cholmod_factor* symbolic = cholmod_analyze_p(&view, given, nullptr, 0, &common);
  CountedOrder order;
  if (symbolic) {
    const int* chosen = static_cast<const int*>(symbolic->Perm);
    order.perm.assign(chosen, chosen + graph.rows());
    order.entries = common.lnz;
  }
  const bool ok = symbolic != nullptr;
  cholmod_free_factor(&symbolic, &common);
  cholmod_finish(&common);
  if (!ok) throw Error("out of memory while ordering the deformation system");
  return order;
}

// The nodes of each of the dissection's sets ordered by CAMD after those of the sets numbered
// below it.
CountedOrder dissected_order(const Eigen::SparseMatrix<double>& graph, std::vector<int>& sets) {
  cholmod_common common;
  cholmod_start(&common);
  cholmod_sparse view = Eigen::viewAsCholmod(graph.selfadjointView<Eigen::Lower>());
  std::vector<int> perm(static_cast<size_t>(graph.rows()));
  const bool ok = cholmod_camd(&view, nullptr, 0, sets.data(), perm.data(), &common);
  cholmod_finish(&common);
  if (!ok) throw Error("out of memory while ordering the deformation system");
  return counted_order(graph, perm.data());
}
#else
// perm[k]: the node eliminated k-th by Eigen's minimum degree (AMD), whatever the order asked.
// graph: lower triangle.
void elimination_order(const Eigen::SparseMatrix<double>& graph, FillOrder,
                       std::vector<int>& perm) {
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  Eigen::AMDOrdering<int>()(graph.selfadjointView<Eigen::Lower>(), order);
  perm.assign(order.indices().data(), order.indices().data() + graph.rows());
}
#endif

}  // namespace

std::vector<int> fill_reducing_rank(const BlockPattern& graph, const std::vector<Vec3>& points,
                                    int leaf, int threads) {
  const int nodes = graph.blocks();
  std::vector<int> rank(static_cast<size_t>(nodes));
  std::iota(rank.begin(), rank.end(), 0);
  if (nodes < 2) return rank;
  std::vector<int> perm;
#ifdef QD_WITH_CHOLMOD
  // AMD's order on another thread while the graph is cut; the one that fills less is kept.
  const Eigen::SparseMatrix<double> lower = scalar_lower(graph);
  std::future<CountedOrder> amd =
      std::async(threads > 1 ? std::launch::async : std::launch::deferred,
                 [&] { return counted_order(lower, nullptr); });
  std::vector<int> sets = coordinate_dissection(graph, points, leaf);
  CountedOrder cut = dissected_order(lower, sets);
  CountedOrder other = amd.get();
  perm = std::move(other.entries < cut.entries ? other.perm : cut.perm);
#else
  (void)points;
  (void)leaf;
  (void)threads;
  elimination_order(scalar_lower(graph), FillOrder::Coordinates, perm);
#endif
  for (int k = 0; k < nodes; ++k) rank[static_cast<size_t>(perm[static_cast<size_t>(k)])] = k;
  return rank;
}

std::vector<int> fill_reducing_rank(const BlockPattern& graph, FillOrder order) {
  const int nodes = graph.blocks();
  std::vector<int> rank(static_cast<size_t>(nodes));
  std::iota(rank.begin(), rank.end(), 0);
  if (nodes < 2) return rank;
  std::vector<int> perm;
  elimination_order(scalar_lower(graph), order, perm);
  for (int k = 0; k < nodes; ++k) rank[static_cast<size_t>(perm[static_cast<size_t>(k)])] = k;
  return rank;
}

std::vector<int> fill_reducing_rank(int nodes, const std::vector<std::pair<int, int>>& edges,
                                    FillOrder order) {
  return fill_reducing_rank(lower_pattern(nodes, edges), order);
}

}  // namespace qd::common
