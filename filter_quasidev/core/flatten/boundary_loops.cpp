#include "flatten/boundary_loops.h"

namespace qd::flatten {

std::vector<std::vector<int>> boundary_loops(const Triangles& F, const EdgeTable& edges) {
  // Boundary half-edges as their faces run them (from → to), and those leaving each vertex.
  std::vector<int> from, to, leaving_first(edges.first.size(), 0);
  for (int e = 0; e < edges.count(); ++e) {
    if (!edges.boundary(e)) continue;
    const int f = edges.faces[e][0];
    for (int k = 0; k < 3; ++k)
      if (edges.of_face[f][k] == e) {
        from.push_back(F(f, k));
        to.push_back(F(f, (k + 1) % 3));
      }
    ++leaving_first[from.back() + 1];
  }
  for (size_t v = 1; v < leaving_first.size(); ++v) leaving_first[v] += leaving_first[v - 1];
  std::vector<int> leaving(from.size()), next(leaving_first.begin(), leaving_first.end() - 1);
  for (size_t h = 0; h < from.size(); ++h) leaving[next[from[h]]++] = static_cast<int>(h);

  std::vector<char> used(from.size(), 0);
  // An unused half-edge leaving v (the first, where a pinched vertex has several), or −1.
  const auto unused_leaving = [&](int v) {
    for (int i = leaving_first[v]; i < leaving_first[v + 1]; ++i)
      if (!used[leaving[i]]) return leaving[i];
    return -1;
  };
  std::vector<std::vector<int>> loops;
  for (size_t start = 0; start < from.size(); ++start) {
    if (used[start]) continue;
    std::vector<int> loop;
    for (int h = static_cast<int>(start); h >= 0; h = unused_leaving(to[h])) {
      used[h] = 1;
      loop.push_back(from[h]);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

int euler_characteristic(const Triangles& F, const EdgeTable& edges, int vertex_count) {
  return vertex_count - edges.count() + static_cast<int>(F.rows());
}

}  // namespace qd::flatten
