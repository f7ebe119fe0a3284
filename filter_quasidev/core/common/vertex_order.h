// Fill-reducing order of a group's free vertices, computed once on the vertex graph (n nodes)
// instead of the 3n×3n system, then used to number the unknowns in 3×3 blocks: the Cholesky
// factor of the coupled system then has the vertex factor's pattern expanded to 3×3 blocks.
#pragma once

#include <utility>
#include <vector>

#include "common/block_pattern.h"

namespace qd::common {

// MinimumDegree: AMD, which orders faster than nested dissection saves where a system is
// factorised a few times or is small (docs/solvers.md). LeastFill: AMD and METIS's nested
// dissection both, keeping the order whose factor has fewer entries; on a garment's large
// panels nested dissection halves the factorisation's flops. Without CHOLMOD, AMD alone.
enum class FillOrder { MinimumDegree, LeastFill };

// Fill-reducing order of a graph with `nodes` nodes and the given undirected edges (i ≠ j).
// Returns rank[v]: the position of node v in the elimination order.
std::vector<int> fill_reducing_rank(int nodes, const std::vector<std::pair<int, int>>& edges,
                                    FillOrder order = FillOrder::MinimumDegree);
// The same for the graph of a block pattern (block_pattern.h: a node per block).
std::vector<int> fill_reducing_rank(const BlockPattern& graph, FillOrder order);

}  // namespace qd::common
