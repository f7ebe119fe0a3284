// Cutting a mesh along edges by duplicating vertices: the corners of a vertex stay one vertex
// only where they are glued across an edge that two faces share and that is not cut, so each
// fan of corners between cut (or boundary, or non-manifold) edges becomes a vertex of its own.
#pragma once

#include <vector>

#include "common/mesh.h"
#include "flatten/common_names.h"
#include "flatten/edge_table.h"

namespace qd::flatten {

struct SplitMesh {
  Triangles F;              // same faces, new vertex indices
  std::vector<int> origin;  // per new vertex: the vertex of the input it is a copy of
};

// F with its edge table; cut: per edge, 1 = cut it open (empty = cut nothing, which still
// separates bow-ties and the faces of non-manifold edges). New vertices are numbered in the
// order of their first corner (face by face), so the result depends on the input only.
SplitMesh split_corners(const Triangles& F, const EdgeTable& edges,
                        const std::vector<char>& cut = {});

}  // namespace qd::flatten
