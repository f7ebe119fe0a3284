// The undirected edges of a triangle mesh with their faces, the edges of each face and the
// edges at each vertex: what cutting a patch to a disk walks over.
#pragma once

#include <array>
#include <vector>

#include "common/mesh.h"
#include "flatten/common_names.h"

namespace qd::flatten {

struct EdgeTable {
  std::vector<std::array<int, 2>> ends;     // per edge: its vertices, lower index first
  std::vector<std::array<int, 2>> faces;    // per edge: its first two faces, −1 where none
  std::vector<char> nonmanifold;            // per edge: it has more than two faces
  std::vector<std::array<int, 3>> of_face;  // per face: edge of corner k → k+1
  std::vector<int> first;                   // edges at vertex v: at[first[v] .. first[v + 1])
  std::vector<int> at;

  int count() const { return static_cast<int>(ends.size()); }
  bool boundary(int e) const { return faces[e][1] < 0; }
  // Two faces meet along e and nothing else does: corners may be glued across it.
  bool interior(int e) const { return faces[e][1] >= 0 && !nonmanifold[e]; }
  int other_end(int e, int v) const { return ends[e][0] == v ? ends[e][1] : ends[e][0]; }
};

// Edges of F (vertex indices in [0, vertex_count)), numbered by (lower, higher) vertex.
EdgeTable edge_table(const Triangles& F, int vertex_count);

}  // namespace qd::flatten
