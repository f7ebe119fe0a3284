// Fill-reducing order of a group's free vertices, computed once on the vertex graph (n nodes)
// instead of the 3n×3n system, then used to number the unknowns in 3×3 blocks: the Cholesky
// factor of the coupled system then has the vertex factor's pattern expanded to 3×3 blocks.
#pragma once

#include <utility>
#include <vector>

#include "common/block_pattern.h"
#include "common/mesh.h"

namespace qd::common {

// MinimumDegree: AMD, which orders faster than nested dissection saves where a system is
// factorised a few times or is small (docs/solvers.md). LeastFill: AMD and METIS's nested
// dissection both, keeping the order whose factor has fewer entries; on a garment's large
// panels nested dissection halves the factorisation's flops. Without CHOLMOD, AMD alone.
// Coordinates: nested dissection by the nodes' coordinates (coordinate_dissection.h), each set
// ordered by CAMD, or AMD's order where its factor has fewer entries; only with the nodes'
// points (AMD without them, and without CHOLMOD).
enum class FillOrder { MinimumDegree, LeastFill, Coordinates };

// Fill-reducing order of a graph with `nodes` nodes and the given undirected edges (i ≠ j).
// Returns rank[v]: the position of node v in the elimination order.
std::vector<int> fill_reducing_rank(int nodes, const std::vector<std::pair<int, int>>& edges,
                                    FillOrder order = FillOrder::MinimumDegree);
// The same for the graph of a block pattern (block_pattern.h: a node per block).
std::vector<int> fill_reducing_rank(const BlockPattern& graph, FillOrder order);
// FillOrder::Coordinates of a graph whose node v lies at points[v], its parts cut down to at most
// `leaf` nodes; with threads > 1, AMD orders on a second thread meanwhile.
std::vector<int> fill_reducing_rank(const BlockPattern& graph, const std::vector<Vec3>& points,
                                    int leaf, int threads = 1);

}  // namespace qd::common
