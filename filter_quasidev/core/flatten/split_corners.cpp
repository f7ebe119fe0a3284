#include "flatten/split_corners.h"

#include "common/disjoint_sets.h"
#include "flatten/common_names.h"

namespace qd::flatten {

SplitMesh split_corners(const Triangles& F, const EdgeTable& edges, const std::vector<char>& cut) {
  DisjointSets corners(3 * static_cast<size_t>(F.rows()));
  for (int e = 0; e < edges.count(); ++e) {
    if (!edges.interior(e) || (!cut.empty() && cut[e])) continue;
    const auto [f, g] = edges.faces[e];
    for (const int v : edges.ends[e]) corners.join(corner_of(F, f, v), corner_of(F, g, v));
  }
  int count = 0;
  const std::vector<int> vertex_of_corner = corners.numbering(&count);
  SplitMesh split;
  split.F.resize(F.rows(), 3);
  split.origin.resize(static_cast<size_t>(count));
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = vertex_of_corner[3 * f + k];
      split.F(f, k) = v;
      split.origin[v] = F(f, k);
    }
  return split;
}

}  // namespace qd::flatten
