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
// An elimination order (perm[k]: the node eliminated k-th) and its factor's entries.
struct CountedOrder {
  std::vector<int> perm;
  double entries = 0;
};

// The given order (not null), or the one CHOLMOD chooses by `order` (of several, the one whose
// factor has fewest entries), with its factor's entries. graph: lower triangle with diagonal.
CountedOrder analysed_order(const Eigen::SparseMatrix<double>& graph, FillOrder order,
                            int* given = nullptr) {
  cholmod_common common;
  cholmod_start(&common);
  common.nmethods = !given && order == FillOrder::LeastFill ? 2 : 1;
  common.method[0].ordering = given ? CHOLMOD_GIVEN : CHOLMOD_AMD;
  common.method[1].ordering = CHOLMOD_METIS;
  common.supernodal = CHOLMOD_SIMPLICIAL;
  cholmod_sparse view = Eigen::viewAsCholmod(graph.selfadjointView<Eigen::Lower>());
  // METIS draws from one random generator per process: two orders computed at once on two
  // threads would each depend on the other's draws, and the result on the thread count.
  static std::mutex metis;
  std::unique_lock<std::mutex> one_at_a_time(metis, std::defer_lock);
  if (common.nmethods == 2) one_at_a_time.lock();
  cholmod_factor* symbolic = cholmod_analyze_p(&view, given, nullptr, 0, &common);
  CountedOrder counted;
  if (symbolic) {
    const int* chosen = static_cast<const int*>(symbolic->Perm);
    counted.perm.assign(chosen, chosen + graph.rows());
    counted.entries = common.lnz;
  }
  const bool ok = symbolic != nullptr;
  cholmod_free_factor(&symbolic, &common);
  cholmod_finish(&common);
  if (!ok) throw Error("out of memory while ordering the deformation system");
  return counted;
}

void elimination_order(const Eigen::SparseMatrix<double>& graph, FillOrder order,
                       std::vector<int>& perm) {
  perm = analysed_order(graph, order).perm;
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
  return analysed_order(graph, FillOrder::Coordinates, perm.data());
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

// rank[v]: the position of node v in the elimination order perm.
std::vector<int> ranks(const std::vector<int>& perm) {
  std::vector<int> rank(perm.size());
  for (size_t k = 0; k < perm.size(); ++k) rank[static_cast<size_t>(perm[k])] = static_cast<int>(k);
  return rank;
}

}  // namespace

std::vector<int> fill_reducing_rank(const BlockPattern& graph, const std::vector<Vec3>& points,
                                    int leaf, int threads) {
  std::vector<int> perm(static_cast<size_t>(graph.blocks()));
  std::iota(perm.begin(), perm.end(), 0);
  if (graph.blocks() < 2) return perm;
#ifdef QD_WITH_CHOLMOD
  // AMD's order on another thread while the graph is cut; the one that fills less is kept.
  const Eigen::SparseMatrix<double> lower = scalar_lower(graph);
  std::future<CountedOrder> amd =
      std::async(threads > 1 ? std::launch::async : std::launch::deferred,
                 [&] { return analysed_order(lower, FillOrder::MinimumDegree); });
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
  return ranks(perm);
}

std::vector<int> fill_reducing_rank(const BlockPattern& graph, FillOrder order) {
  std::vector<int> perm(static_cast<size_t>(graph.blocks()));
  std::iota(perm.begin(), perm.end(), 0);
  if (graph.blocks() < 2) return perm;
  elimination_order(scalar_lower(graph), order, perm);
  return ranks(perm);
}

std::vector<int> fill_reducing_rank(int nodes, const std::vector<std::pair<int, int>>& edges,
                                    FillOrder order) {
  return fill_reducing_rank(lower_pattern(nodes, edges), order);
}

}  // namespace qd::common
