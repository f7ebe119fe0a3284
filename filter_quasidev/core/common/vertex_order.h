// Fill-reducing order of a group's free vertices, computed once on the vertex graph (n nodes)
// instead of the 3n×3n system, then used to number the unknowns in 3×3 blocks: the Cholesky
// factor of the coupled system then has the vertex factor's pattern expanded to 3×3 blocks.
#pragma once

#include <utility>
#include <vector>

namespace qd::common {

// Fill-reducing order of a graph with `nodes` nodes and the given undirected edges (i ≠ j):
// minimum degree (AMD), which orders faster than nested dissection saves (docs/solvers.md).
// Returns rank[v]: the position of node v in the elimination order.
std::vector<int> fill_reducing_rank(int nodes, const std::vector<std::pair<int, int>>& edges);

}  // namespace qd::common
