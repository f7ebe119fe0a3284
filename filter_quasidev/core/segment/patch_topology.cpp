// Counts from the mesh's sorted face edges; boundary loops by union-find over the vertices of
// each patch's boundary edges (two loops touching at a vertex count as one).
#include "segment/patch_topology.h"

#include <array>

#include "segment/partition.h"

namespace qd::segment {

namespace {

int find(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

}  // namespace

std::vector<PatchTopology> patch_topology(const Triangles& F, Eigen::Index vertex_count,
                                          const std::vector<int>& patch, int count) {
  std::vector<PatchTopology> t(static_cast<size_t>(count));
  const std::vector<std::vector<int>> faces = faces_by_chart(patch, count);
  std::vector<int> stamp(static_cast<size_t>(vertex_count), -1);
  for (int p = 0; p < count; ++p) {
    t[p].faces = static_cast<int>(faces[p].size());
    for (const int f : faces[p])
      for (int k = 0; k < 3; ++k)
        if (stamp[F(f, k)] != p) {
          stamp[F(f, k)] = p;
          ++t[p].vertices;
        }
  }

  // Edges per patch; an edge with one face of patch p is on p's boundary.
  std::vector<std::vector<std::array<int, 2>>> boundary(static_cast<size_t>(count));
  const std::vector<FaceEdge> edges = sorted_face_edges(F, vertex_count);
  for (size_t i = 0; i < edges.size();) {
    size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    for (size_t m = i; m < j; ++m) {
      const int p = patch[edges[m].face];
      size_t same = 0, earlier = 0;
      for (size_t q = i; q < j; ++q) {
        same += patch[edges[q].face] == p;
        earlier += q < m && patch[edges[q].face] == p;
      }
      if (earlier > 0) continue;  // counted at its first face of patch p
      ++t[p].edges;
      if (same == 1) boundary[p].push_back({edges[i].lo, edges[i].hi});
    }
    i = j;
  }

  std::vector<int> parent(static_cast<size_t>(vertex_count), -1);
  for (int p = 0; p < count; ++p) {
    int loops = 0;
    for (const auto& e : boundary[p])
      for (const int v : e)
        if (parent[v] < 0) {
          parent[v] = v;
          ++loops;
        }
    for (const auto& e : boundary[p]) {
      const int a = find(parent, e[0]), b = find(parent, e[1]);
      if (a != b) {
        parent[a] = b;
        --loops;
      }
    }
    t[p].boundary_loops = loops;
    for (const auto& e : boundary[p]) parent[e[0]] = parent[e[1]] = -1;
  }
  return t;
}

}  // namespace qd::segment
