// A pattern piece before flattening: one edge-connected component of one patch, as a mesh of
// its own (a vertex on a seam or a cut appears in every piece, or twice in one piece).
#pragma once

#include <vector>

#include "common/mesh.h"
#include "flatten/common_names.h"

namespace qd::flatten {

struct Piece {
  int patch = 0;            // patch id of its faces
  int component = 0;        // 0, 1, … among the edge-connected components of that patch
  int components = 1;       // how many the patch has
  std::vector<int> face;    // per local face: the face of the mesh
  std::vector<int> vertex;  // per local vertex: the vertex of the mesh it is a copy of
  Positions V;
  Triangles F;
};

// Local copy of a piece's mesh after cutting it: vertex v of `split` is a copy of vertex
// origin[v] of piece.V.
void renumber_vertices(Piece& piece, const Triangles& F, const std::vector<int>& origin);

// Pieces of a mesh: per patch (ascending id; patch empty = one patch 0), its faces split into
// edge-connected components (ordered by their first face). Faces meet only across edges that
// exactly two of them share: bow-tie vertices and non-manifold edges separate.
std::vector<Piece> extract_pieces(const Positions& V, const Triangles& F,
                                  const std::vector<int>& patch);

}  // namespace qd::flatten
