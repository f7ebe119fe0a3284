// Shortest paths along mesh edges (Dijkstra 1959), edge length = Euclidean length in 3D.
#pragma once

#include <vector>

#include "common/mesh.h"
#include "flatten/common_names.h"
#include "flatten/edge_table.h"

namespace qd::flatten {

struct ShortestPaths {
  std::vector<double> distance;  // per vertex, from the nearest source; +inf if unreachable
  std::vector<int> parent_edge;  // per vertex, the last edge of its path; −1 at sources
};

// From every vertex of `sources` at once (their distance is 0). Ties are broken by vertex
// index, so the paths depend on the input only.
ShortestPaths shortest_paths(const Positions& V, const EdgeTable& edges,
                             const std::vector<int>& sources);

// The edges of the path from v back to its source, in that order.
std::vector<int> path_to_source(const ShortestPaths& paths, const EdgeTable& edges, int v);

// Length of edge e.
double edge_length(const Positions& V, const EdgeTable& edges, int e);

}  // namespace qd::flatten
