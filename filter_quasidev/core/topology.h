// Combinatorial facts about the mesh: boundary, seams, used vertices, manifoldness, orientation.
#pragma once

#include <vector>

#include "mesh.h"

namespace qd {

struct Topology {
  std::vector<char> used;           // vertex referenced by at least one face
  std::vector<char> boundary;       // vertex on an open boundary edge (edge with one face)
  std::vector<char> seam;           // vertex whose faces belong to more than one patch
  int nonmanifold_edges = 0;        // edges with more than two faces
  int nonmanifold_vertices = 0;     // vertices whose face fan is not one connected fan
  int first_nonmanifold_edge[2] = {-1, -1};  // an example, for messages
  int first_nonmanifold_vertex = -1;
  int misoriented_edges = 0;        // edges along which two faces of one patch run the same way
  int first_misoriented_edge[2] = {-1, -1};   // an example (from, to), its faces and patch
  int first_misoriented_faces[2] = {-1, -1};
  int first_misoriented_patch = 0;
};

// patch: patch id per face (empty = one patch). Face indices must lie in [0, vertex_count)
// (validate() checks that first).
Topology analyse_topology(const Triangles& F, int vertex_count, const std::vector<int>& patch);

}  // namespace qd
