// Combinatorial facts about the mesh: boundary, seams, used vertices, manifoldness, orientation,
// duplicate faces and patches too small to fit.
#pragma once

#include <vector>

#include "common/mesh.h"

namespace qd::common {

// Fewest faces a patch may have: fewer cannot give a Gauss image to fit (Step 1).
constexpr int kMinPatchFaces = 4;

struct Topology {
  std::vector<char> used;                    // vertex referenced by at least one face
  std::vector<char> boundary;                // vertex on an open boundary edge (edge with one face)
  std::vector<char> seam;                    // vertex whose faces belong to more than one patch
  std::vector<char> nonmanifold;             // vertex on an edge with more than two faces
  int nonmanifold_edges = 0;                 // edges with more than two faces
  int nonmanifold_vertices = 0;              // vertices whose face fan is not one connected fan
  int first_nonmanifold_edge[2] = {-1, -1};  // an example, for messages
  int first_nonmanifold_vertex = -1;
  int misoriented_edges = 0;  // edges along which two faces of one patch run the same way
  int first_misoriented_edge[2] = {-1, -1};  // an example (from, to), its faces and patch
  int first_misoriented_faces[2] = {-1, -1};
  int first_misoriented_patch = 0;
  int duplicate_faces = 0;                  // faces with the same three vertices as an earlier face
  int first_duplicate_faces[2] = {-1, -1};  // an example pair
  std::vector<char> in_small_patch;    // vertex of a patch with fewer than kMinPatchFaces faces
  int patches = 0;                     // distinct patch ids
  int small_patches = 0;               // patches with fewer than kMinPatchFaces faces
  int first_small_patch[2] = {-1, 0};  // an example: its id and its face count
};

// patch: patch id per face (empty = one patch). Face indices must lie in [0, vertex_count)
// (check_face_indices() in common/validate_mesh.h checks that first).
Topology analyse_topology(const Triangles& F, int vertex_count, const std::vector<int>& patch);

}  // namespace qd::common
