// Boundary, seam and used vertices, non-manifold edges and vertices, misoriented edges, from
// the mesh's face edges sorted in linear time.
#include "common/topology.h"

#include <algorithm>
#include <cassert>
#include <map>
#include <numeric>

#include "common/disjoint_sets.h"

namespace qd::common {

namespace {

// Face f runs along its edge {a, b} from a to b.
bool runs_forward(const Triangles& F, int f, int a, int b) {
  for (int k = 0; k < 3; ++k)
    if (F(f, k) == a) return F(f, (k + 1) % 3) == b;
  return false;
}

int patch_of(const std::vector<int>& patch, int f) { return patch.empty() ? 0 : patch[f]; }

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

// The vertex of face e.face that is not on its edge e.
int third_vertex(const Triangles& F, const FaceEdge& e) {
  for (int k = 0; k < 3; ++k)
    if (F(e.face, k) != e.lo && F(e.face, k) != e.hi) return F(e.face, k);
  return -1;
}

// Faces of one edge (edges[i, j)) that share their third vertex too: duplicates. Counted at the
// edge of a face's two lowest vertices only, so each pair once.
void note_duplicates(const Triangles& F, const std::vector<FaceEdge>& edges, size_t i, size_t j,
                     Topology& t) {
  std::vector<std::pair<int, int>> third;  // (third vertex, face)
  for (size_t m = i; m < j; ++m) {
    const int v = third_vertex(F, edges[m]);
    if (v > edges[m].hi) third.emplace_back(v, edges[m].face);
  }
  std::sort(third.begin(), third.end());
  for (size_t m = 1; m < third.size(); ++m) {
    if (third[m].first != third[m - 1].first || t.duplicate_faces++ > 0) continue;
    t.first_duplicate_faces[0] = third[m - 1].second;
    t.first_duplicate_faces[1] = third[m].second;
  }
}

// Patches too small to fit and their vertices: they stay as they are while the rest is done.
void mark_small_patches(const Triangles& F, const std::vector<int>& patch, Topology& t) {
  std::map<int, int> faces;
  for (int f = 0; f < F.rows(); ++f) ++faces[patch_of(patch, f)];
  t.patches = static_cast<int>(faces.size());
  for (const auto& [id, count] : faces) {
    if (count >= kMinPatchFaces || t.small_patches++ > 0) continue;
    t.first_small_patch[0] = id;
    t.first_small_patch[1] = count;
  }
  if (t.small_patches == 0) return;
  for (int f = 0; f < F.rows(); ++f)
    if (faces[patch_of(patch, f)] < kMinPatchFaces)
      for (int k = 0; k < 3; ++k) t.in_small_patch[F(f, k)] = 1;
}

// One undirected edge and its faces edges[i, j): boundary, non-manifold, duplicate faces or a
// misoriented pair of faces of one patch.
void classify_edge(const Triangles& F, const std::vector<int>& patch,
                   const std::vector<FaceEdge>& edges, size_t i, size_t j, Topology& t) {
  const FaceEdge& e = edges[i];
  const size_t faces = j - i;
  if (faces > 2 || (faces == 2 && third_vertex(F, e) == third_vertex(F, edges[i + 1])))
    note_duplicates(F, edges, i, j, t);
  if (faces == 1) {
    t.boundary[e.lo] = 1;
    t.boundary[e.hi] = 1;
  } else if (faces > 2) {
    t.nonmanifold[e.lo] = 1;
    t.nonmanifold[e.hi] = 1;
    if (t.nonmanifold_edges++ == 0) {
      t.first_nonmanifold_edge[0] = e.lo;
      t.first_nonmanifold_edge[1] = e.hi;
    }
  } else {
    const int f = e.face, g = edges[i + 1].face;
    const bool forward = runs_forward(F, f, e.lo, e.hi);
    if (patch_of(patch, f) == patch_of(patch, g) && forward == runs_forward(F, g, e.lo, e.hi) &&
        t.misoriented_edges++ == 0) {
      t.first_misoriented_edge[0] = forward ? e.lo : e.hi;
      t.first_misoriented_edge[1] = forward ? e.hi : e.lo;
      t.first_misoriented_faces[0] = f;
      t.first_misoriented_faces[1] = g;
      t.first_misoriented_patch = patch_of(patch, f);
    }
  }
}

}  // namespace

Topology analyse_topology(const Triangles& F, int vertex_count, const std::vector<int>& patch) {
  // Validation (check_face_indices) ran first: every index below reads inside the per-vertex
  // flags.
  assert(F.size() == 0 || (F.minCoeff() >= 0 && F.maxCoeff() < vertex_count));
  assert(patch.empty() || patch.size() == static_cast<size_t>(F.rows()));
  const auto n = static_cast<size_t>(vertex_count);
  Topology t;
  t.used.assign(n, 0);
  t.boundary.assign(n, 0);
  t.seam.assign(n, 0);
  t.nonmanifold.assign(n, 0);
  t.in_small_patch.assign(n, 0);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) t.used[F(f, k)] = 1;
  mark_seams(F, patch, t);
  mark_small_patches(F, patch, t);

  // Edges: faces per undirected edge; fans joined across every shared edge.
  const std::vector<FaceEdge> edges = sorted_face_edges(F, vertex_count);
  DisjointSets corners(3 * static_cast<size_t>(F.rows()));  // a set of corners per vertex fan
  for (size_t i = 0; i < edges.size();) {
    size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    classify_edge(F, patch, edges, i, j, t);
    for (size_t m = i + 1; m < j; ++m) {
      const FaceEdge& e = edges[i];
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

}  // namespace qd::common
