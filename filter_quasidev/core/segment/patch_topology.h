// Topology of each patch of a labelled mesh: vertices, edges, faces, boundary loops, and whether
// the patch is a topological disk (it flattens without a further cut).
#pragma once

#include <vector>

#include "common/mesh.h"
#include "segment/common_names.h"

namespace qd::segment {

struct PatchTopology {
  int vertices = 0, edges = 0, faces = 0;
  int boundary_loops = 0;  // connected sets of boundary edges (edges with one face in the patch)
  int euler() const { return vertices - edges + faces; }
  bool disk() const { return euler() == 1 && boundary_loops == 1; }
};

// patch: an id in [0, count) per face.
std::vector<PatchTopology> patch_topology(const Triangles& F, Eigen::Index vertex_count,
                                          const std::vector<int>& patch, int count);

}  // namespace qd::segment
