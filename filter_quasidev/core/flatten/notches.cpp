#include "flatten/notches.h"

#include <algorithm>
#include <cmath>

namespace qd::flatten {

namespace {

// The seam edges (listed at least twice) as an adjacency list per vertex.
std::vector<std::vector<int>> seam_graph(std::vector<std::array<int, 2>>& edges, size_t vertices) {
  for (auto& e : edges)
    if (e[0] > e[1]) std::swap(e[0], e[1]);
  std::sort(edges.begin(), edges.end());
  std::vector<std::vector<int>> next(vertices);
  for (size_t i = 1; i < edges.size(); ++i) {
    if (edges[i] != edges[i - 1] || (i > 1 && edges[i - 1] == edges[i - 2])) continue;
    next[edges[i][0]].push_back(edges[i][1]);
    next[edges[i][1]].push_back(edges[i][0]);
  }
  return next;
}

// Marks the chain's vertices nearest to every `spacing` of arc length from its first vertex,
// and its last vertex (a closed chain's last vertex is its first).
void mark_chain(const Positions& V, const std::vector<int>& chain, double spacing,
                std::vector<char>& notch) {
  std::vector<double> at(chain.size(), 0);
  for (size_t i = 1; i < chain.size(); ++i)
    at[i] = at[i - 1] + (V.row(chain[i]) - V.row(chain[i - 1])).norm();
  const int parts = std::max(1, static_cast<int>(std::lround(at.back() / spacing)));
  size_t i = 0;
  for (int k = 0; k <= parts; ++k) {
    const double target = at.back() * k / parts;
    while (i + 1 < chain.size() && std::abs(at[i + 1] - target) <= std::abs(at[i] - target)) ++i;
    notch[chain[i]] = 1;
  }
}

}  // namespace

std::vector<char> notch_vertices(const Positions& V, std::vector<std::array<int, 2>> boundary_edges,
                                 double spacing) {
  const size_t n = static_cast<size_t>(V.rows());
  const std::vector<std::vector<int>> next = seam_graph(boundary_edges, n);
  std::vector<char> notch(n, 0);
  std::vector<std::vector<char>> walked(n);
  for (size_t v = 0; v < n; ++v) walked[v].assign(next[v].size(), 0);
  // Walks from v along its k-th seam edge until a junction or back to the start.
  const auto walk = [&](int v, size_t k) {
    std::vector<int> chain = {v};
    for (;;) {
      walked[v][k] = 1;
      const int w = next[v][k];
      const auto back = std::find(next[w].begin(), next[w].end(), v) - next[w].begin();
      walked[w][static_cast<size_t>(back)] = 1;
      chain.push_back(w);
      if (next[w].size() != 2 || w == chain.front()) break;
      k = next[w][0] == v ? 1 : 0;
      v = w;
    }
    mark_chain(V, chain, spacing, notch);
  };
  for (int pass = 0; pass < 2; ++pass)  // chains from junctions first, then closed loops
    for (size_t v = 0; v < n; ++v)
      if ((next[v].size() != 2) == (pass == 0))
        for (size_t k = 0; k < next[v].size(); ++k)
          if (!walked[v][k]) walk(static_cast<int>(v), k);
  return notch;
}

}  // namespace qd::flatten
