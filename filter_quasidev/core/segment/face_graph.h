// The faces' edge adjacency that chart growing walks. Side k of face f is its edge from
// F(f, k) to F(f, (k+1) % 3). A side has no neighbour (−1) on an open boundary and where a
// border is kept: a non-manifold edge (more than two faces), an edge along which the two faces
// run the same way (inconsistent orientation, so every patch stays consistently oriented), an
// edge between different regions (existing patches, selected and unselected faces), and, once
// remove_creases() has run, a crease (normals differing by more than the crease angle).
#pragma once

#include <array>
#include <vector>

#include "common/mesh.h"
#include "segment/common_names.h"
#include "segment/face_geometry.h"

namespace qd::segment {

struct FaceGraph {
  std::vector<std::array<int, 3>> neighbour;       // face across side k, or −1
  std::vector<std::array<double, 3>> side_length;  // length of side k
  int nonmanifold_edges = 0;
  int misoriented_edges = 0;
  std::vector<std::array<int, 2>> creases;  // the two faces of each crease cut, lower first
  int region_edges = 0;                     // edges between two regions
};

// region: a label per face (empty = one region).
FaceGraph face_graph(const Positions& V, const Triangles& F, const std::vector<int>& region);

// Cuts the sides whose faces' normals differ by more than `crease` radians.
void remove_creases(FaceGraph& graph, const FaceGeometry& g, double crease);

}  // namespace qd::segment
