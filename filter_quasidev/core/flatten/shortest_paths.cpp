#include "flatten/shortest_paths.h"

#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace qd::flatten {

double edge_length(const Positions& V, const EdgeTable& edges, int e) {
  return (V.row(edges.ends[e][0]) - V.row(edges.ends[e][1])).norm();
}

ShortestPaths shortest_paths(const Positions& V, const EdgeTable& edges,
                             const std::vector<int>& sources) {
  const size_t n = static_cast<size_t>(V.rows());
  ShortestPaths p{std::vector<double>(n, std::numeric_limits<double>::infinity()),
                  std::vector<int>(n, -1)};
  using Entry = std::pair<double, int>;  // (distance, vertex): equal distances pop by index
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (const int s : sources) {
    p.distance[s] = 0;
    queue.emplace(0.0, s);
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > p.distance[v]) continue;
    for (int i = edges.first[v]; i < edges.first[v + 1]; ++i) {
      const int e = edges.at[i], w = edges.other_end(e, v);
      const double through = d + edge_length(V, edges, e);
      if (through >= p.distance[w]) continue;
      p.distance[w] = through;
      p.parent_edge[w] = e;
      queue.emplace(through, w);
    }
  }
  return p;
}

std::vector<int> path_to_source(const ShortestPaths& paths, const EdgeTable& edges, int v) {
  std::vector<int> path;
  for (int e = paths.parent_edge[v]; e >= 0; e = paths.parent_edge[v]) {
    path.push_back(e);
    v = edges.other_end(e, v);
  }
  return path;
}

}  // namespace qd::flatten
