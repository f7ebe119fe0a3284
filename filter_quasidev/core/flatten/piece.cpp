#include "flatten/piece.h"

#include <cassert>
#include <map>

#include "common/disjoint_sets.h"
#include "flatten/common_names.h"
#include "flatten/edge_table.h"
#include "flatten/split_corners.h"

namespace qd::flatten {

void renumber_vertices(Piece& piece, const Triangles& F, const std::vector<int>& origin) {
  assert(origin.size() >= static_cast<size_t>(F.size() > 0 ? F.maxCoeff() + 1 : 0));
  Positions V(static_cast<Eigen::Index>(origin.size()), 3);
  std::vector<int> vertex(origin.size());
  for (size_t v = 0; v < origin.size(); ++v) {
    V.row(static_cast<Eigen::Index>(v)) = piece.V.row(origin[v]);
    vertex[v] = piece.vertex[static_cast<size_t>(origin[v])];
  }
  piece.V = std::move(V);
  piece.vertex = std::move(vertex);
  piece.F = F;
}

namespace {

// The given faces as a mesh of their own, vertices numbered in order of first use. local: −1
// per vertex of V, used as the vertex map and left as it was found.
Piece local_mesh(const Positions& V, const Triangles& F, int patch, const std::vector<int>& faces,
                 std::vector<int>& local) {
  Piece p;
  p.patch = patch;
  p.face = faces;
  p.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t i = 0; i < faces.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      int& v = local[F(faces[i], k)];
      if (v < 0) {
        v = static_cast<int>(p.vertex.size());
        p.vertex.push_back(F(faces[i], k));
      }
      p.F(static_cast<Eigen::Index>(i), k) = v;
    }
  p.V.resize(static_cast<Eigen::Index>(p.vertex.size()), 3);
  for (size_t v = 0; v < p.vertex.size(); ++v) {
    p.V.row(static_cast<Eigen::Index>(v)) = V.row(p.vertex[v]);
    local[p.vertex[v]] = -1;
  }
  return p;
}

// Component c of `whole`: its faces (local to whole); local as for local_mesh.
Piece component_of(const Piece& whole, const std::vector<int>& faces, int c,
                   std::vector<int>& local) {
  Piece p = local_mesh(whole.V, whole.F, whole.patch, faces, local);
  for (int& f : p.face) f = whole.face[static_cast<size_t>(f)];
  for (int& v : p.vertex) v = whole.vertex[static_cast<size_t>(v)];
  p.component = c;
  return p;
}

}  // namespace

std::vector<Piece> extract_pieces(const Positions& V, const Triangles& F,
                                  const std::vector<int>& patch) {
  std::map<int, std::vector<int>> faces_of_patch;
  for (int f = 0; f < F.rows(); ++f) faces_of_patch[patch.empty() ? 0 : patch[f]].push_back(f);
  std::vector<Piece> pieces;
  std::vector<int> local(static_cast<size_t>(V.rows()), -1);
  for (const auto& [id, faces] : faces_of_patch) {
    Piece whole = local_mesh(V, F, id, faces, local);
    const SplitMesh split =
        split_corners(whole.F, edge_table(whole.F, static_cast<int>(whole.V.rows())));
    renumber_vertices(whole, split.F, split.origin);
    DisjointSets linked(static_cast<size_t>(whole.V.rows()));
    for (int f = 0; f < whole.F.rows(); ++f) {
      linked.join(whole.F(f, 0), whole.F(f, 1));
      linked.join(whole.F(f, 0), whole.F(f, 2));
    }
    int count = 0;
    const std::vector<int> of_vertex = linked.numbering(&count);
    std::vector<std::vector<int>> faces_of(static_cast<size_t>(count));
    for (int f = 0; f < whole.F.rows(); ++f) faces_of[of_vertex[whole.F(f, 0)]].push_back(f);
    const size_t first = pieces.size();
    if (count == 1) {
      pieces.push_back(std::move(whole));
    } else {
      std::vector<int> whole_local(static_cast<size_t>(whole.V.rows()), -1);
      for (int c = 0; c < count; ++c)
        pieces.push_back(component_of(whole, faces_of[c], c, whole_local));
    }
    for (size_t k = first; k < pieces.size(); ++k) {
      pieces[k].components = count;
      // Every local face and vertex maps to one of the mesh.
      assert(pieces[k].face.size() == static_cast<size_t>(pieces[k].F.rows()) &&
             pieces[k].vertex.size() == static_cast<size_t>(pieces[k].V.rows()));
    }
  }
  return pieces;
}

}  // namespace qd::flatten
