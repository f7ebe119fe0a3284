// Boundary, seam and used vertices, non-manifold edges and vertices, from one sort of the
// mesh's half-edges (O(n log n)).
#include "topology.h"

#include <algorithm>
#include <numeric>

namespace qd {

namespace {

struct HalfEdge {
  int lo, hi;  // undirected edge, lo < hi
  int face;
  bool operator<(const HalfEdge& o) const {
    return lo != o.lo ? lo < o.lo : hi != o.hi ? hi < o.hi : face < o.face;
  }
};

std::vector<HalfEdge> sorted_half_edges(const Triangles& F) {
  std::vector<HalfEdge> edges;
  edges.reserve(3 * static_cast<size_t>(F.rows()));
  for (int f = 0; f < F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k);
      const int b = F(f, (k + 1) % 3);
      edges.push_back({std::min(a, b), std::max(a, b), f});
    }
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

// Union-find over face corners (3·f + k); corners of one vertex end up in one set per fan.
class Corners {
 public:
  explicit Corners(size_t count) : parent_(count) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int find(int c) {
    while (parent_[c] != c) {
      parent_[c] = parent_[parent_[c]];
      c = parent_[c];
    }
    return c;
  }
  void join(int a, int b) { parent_[find(a)] = find(b); }

 private:
  std::vector<int> parent_;
};

int corner_of(const Triangles& F, int f, int v) {
  for (int k = 0; k < 3; ++k)
    if (F(f, k) == v) return 3 * f + k;
  return -1;
}

void mark_seams(const Triangles& F, const std::vector<int>& patch, Topology& t) {
  if (patch.empty()) return;
  std::vector<int> first_patch(t.used.size(), 0);
  std::vector<char> seen(t.used.size(), 0);
  for (int f = 0; f < F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int v = F(f, k);
      if (!seen[v]) {
        seen[v] = 1;
        first_patch[v] = patch[f];
      } else if (first_patch[v] != patch[f]) {
        t.seam[v] = 1;
      }
    }
  }
}

}  // namespace

Topology analyse_topology(const Triangles& F, int vertex_count, const std::vector<int>& patch) {
  const auto n = static_cast<size_t>(vertex_count);
  Topology t;
  t.used.assign(n, 0);
  t.boundary.assign(n, 0);
  t.seam.assign(n, 0);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) t.used[F(f, k)] = 1;
  mark_seams(F, patch, t);

  // Edges: faces per undirected edge; fans joined across every shared edge.
  const std::vector<HalfEdge> edges = sorted_half_edges(F);
  Corners corners(3 * static_cast<size_t>(F.rows()));
  for (size_t i = 0; i < edges.size();) {
    size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    const HalfEdge& e = edges[i];
    const size_t faces = j - i;
    if (faces == 1) {
      t.boundary[e.lo] = 1;
      t.boundary[e.hi] = 1;
    } else if (faces > 2 && t.nonmanifold_edges++ == 0) {
      t.first_nonmanifold_edge[0] = e.lo;
      t.first_nonmanifold_edge[1] = e.hi;
    }
    for (size_t m = i + 1; m < j; ++m) {
      corners.join(corner_of(F, edges[m].face, e.lo), corner_of(F, e.face, e.lo));
      corners.join(corner_of(F, edges[m].face, e.hi), corner_of(F, e.face, e.hi));
    }
    i = j;
  }

  // A vertex whose corners form more than one set has more than one fan.
  std::vector<int> fans(n, 0);
  for (int c = 0; c < 3 * static_cast<int>(F.rows()); ++c)
    if (corners.find(c) == c) ++fans[F(c / 3, c % 3)];
  for (int v = 0; v < vertex_count; ++v) {
    if (fans[v] > 1 && t.nonmanifold_vertices++ == 0) t.first_nonmanifold_vertex = v;
  }
  return t;
}

}  // namespace qd
