// Mesh checks (docs/design.md "Bad input"): each says what is wrong and what to do. All O(n log n).
#include "common/validate_mesh.h"

#include <algorithm>

#include "common/error.h"
#include "common/message_text.h"

namespace qd::common {

namespace {

int count_flags(const std::vector<char>& flags) {
  return static_cast<int>(std::count(flags.begin(), flags.end(), 1));
}

}  // namespace

void check_not_empty(const Positions& V, const Triangles& F) {
  if (V.rows() == 0) throw Error("The mesh has no vertices: load a triangle mesh first.");
  if (F.rows() == 0)
    throw Error(
        "The mesh has no faces (a point cloud?): the filter needs a triangle mesh; "
        "reconstruct a surface first.");
}

void check_coordinates(const Positions& V) {
  int bad = 0;
  int first = -1;
  for (int v = 0; v < V.rows(); ++v) {
    if (V.row(v).allFinite()) continue;
    if (bad++ == 0) first = v;
  }
  if (bad > 0)
    throw Error("The mesh has " + count_text(bad, "vertex", "vertices") +
                " with NaN or infinite coordinates (first: vertex " + to_text(first) +
                "): remove or repair them before running the filter.");
}

void check_face_indices(const Triangles& F, int vertex_count) {
  for (int f = 0; f < F.rows(); ++f) {
    const int a = F(f, 0), b = F(f, 1), c = F(f, 2);
    for (const int v : {a, b, c})
      if (v < 0 || v >= vertex_count)
        throw Error("Face " + to_text(f) + " refers to vertex " + to_text(v) +
                    " but the mesh has only " + to_text(vertex_count) +
                    " vertices: the file is corrupt; re-export the mesh.");
    if (a == b || b == c || c == a)
      throw Error("Face " + to_text(f) + " uses vertex " + to_text(a == b || a == c ? a : b) +
                  " twice: remove degenerate faces first (MeshLab: Filters > Cleaning and "
                  "Repairing > Remove Zero Area Faces).");
  }
}

void check_zero_area(const Positions& V, const Triangles& F) {
  const double ae = average_edge_length(V, F);
  const double threshold = kZeroAreaRatio * ae * ae;
  int bad = 0;
  int first = -1;
  for (int f = 0; f < F.rows(); ++f) {
    if (face_area(V, F, f) >= threshold && threshold > 0) continue;
    if (bad++ == 0) first = f;
  }
  if (bad > 0)
    throw Error("The mesh has " + count_text(bad, "zero-area face", "zero-area faces") +
                " (first: face " + to_text(first) +
                "): remove them first (MeshLab: Filters > Cleaning and Repairing > Remove Zero "
                "Area Faces).");
}

// Duplicate faces also make their edges look misoriented: a job checks them first.
void check_duplicate_faces(const Topology& t) {
  if (t.duplicate_faces > 0)
    throw Error("The mesh has " +
                count_text(t.duplicate_faces, "duplicate face", "duplicate faces") +
                " (first: faces " + to_text(t.first_duplicate_faces[0]) + " and " +
                to_text(t.first_duplicate_faces[1]) +
                " use the same vertices): remove them first (MeshLab: Filters > Cleaning and "
                "Repairing > Remove Duplicate Faces).");
}

void check_orientation(const Topology& t) {
  if (t.misoriented_edges > 0)
    throw Error("Patch " + to_text(t.first_misoriented_patch) +
                " is not consistently oriented (faces " + to_text(t.first_misoriented_faces[0]) +
                " and " + to_text(t.first_misoriented_faces[1]) + " run along edge " +
                to_text(t.first_misoriented_edge[0]) + "-" + to_text(t.first_misoriented_edge[1]) +
                " the same way; " + count_text(t.misoriented_edges, "such edge", "such edges") +
                "): fix it first (MeshLab: Filters > Normals, Curvatures and Orientation > "
                "Re-Orient all faces coherently).");
}

std::vector<std::string> mesh_warnings(const Topology& t) {
  std::vector<std::string> out;
  if (t.nonmanifold_edges > 0)
    out.push_back(count_text(t.nonmanifold_edges, "non-manifold edge", "non-manifold edges") +
                  " (more than two faces; first: between vertices " +
                  to_text(t.first_nonmanifold_edge[0]) + " and " +
                  to_text(t.first_nonmanifold_edge[1]) + "): their " +
                  count_text(count_flags(t.nonmanifold), "vertex is", "vertices are") +
                  " kept fixed and left out of the curvature figures; to process them, repair "
                  "the edges (MeshLab: Filters > Cleaning and Repairing > Repair non Manifold "
                  "Edges).");
  return out;
}

}  // namespace qd::common
