#include "flatten/edge_table.h"

namespace qd::flatten {

EdgeTable edge_table(const Triangles& F, int vertex_count) {
  EdgeTable t;
  t.of_face.resize(static_cast<size_t>(F.rows()));
  const std::vector<FaceEdge> sorted = sorted_face_edges(F, vertex_count);
  for (size_t i = 0; i < sorted.size(); ++i) {
    const FaceEdge& e = sorted[i];
    const bool same = i > 0 && sorted[i - 1].lo == e.lo && sorted[i - 1].hi == e.hi;
    if (!same) {
      t.ends.push_back({e.lo, e.hi});
      t.faces.push_back({e.face, -1});
      t.nonmanifold.push_back(0);
    } else if (t.faces.back()[1] < 0) {
      t.faces.back()[1] = e.face;
    } else {
      t.nonmanifold.back() = 1;
    }
    const int edge = t.count() - 1;
    for (int k = 0; k < 3; ++k) {
      const int a = F(e.face, k), b = F(e.face, (k + 1) % 3);
      if ((a == e.lo && b == e.hi) || (a == e.hi && b == e.lo)) t.of_face[e.face][k] = edge;
    }
  }
  t.first.assign(static_cast<size_t>(vertex_count) + 1, 0);
  for (const auto& ends : t.ends) {
    ++t.first[ends[0] + 1];
    ++t.first[ends[1] + 1];
  }
  for (size_t v = 1; v < t.first.size(); ++v) t.first[v] += t.first[v - 1];
  t.at.resize(2 * t.ends.size());
  std::vector<int> next(t.first.begin(), t.first.end() - 1);
  for (int e = 0; e < t.count(); ++e)
    for (const int v : t.ends[e]) t.at[next[v]++] = e;
  return t;
}

}  // namespace qd::flatten
