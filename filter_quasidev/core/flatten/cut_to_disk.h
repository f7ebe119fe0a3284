// Cutting a piece open until it is a topological disk, the only shape that flattens to one
// pattern piece. What is cut, by the piece's topology (b boundary loops, genus g):
//  - b ≥ 2 (a tube, a panel with holes): b − 1 shortest edge paths, each joining the loops
//    joined so far (starting with the longest loop) to the nearest other loop; a tube gets
//    exactly one shortest cut between its two ends.
//  - g ≥ 1 (handles): the 2g loops of the greedy shortest system of loops through the
//    boundary (Erickson & Whittlesey 2005, "Greedy optimal homotopy and homology generators":
//    shortest-path tree T from the boundary, a maximum spanning tree of the dual graph over the
//    edges not in T weighted by the length of the loop each closes, and the 2g edges left).
//  - b = 0 (a closed piece): the same loops through the vertex farthest from vertex 0; with
//    g = 0 a slit along the shortest path from there to the vertex farthest from it.
// A closed or handled piece flattens with large distortion; it is flattened anyway and the
// note says what was cut, so the user can split the patch instead.
#pragma once

#include <string>

#include "flatten/piece.h"

namespace qd::flatten {

struct DiskCut {
  int joining_paths = 0;  // paths joining boundary loops (b − 1)
  int handle_loops = 0;   // loops cutting handles (2g)
  bool slit = false;      // a closed genus-0 piece slit open
  int edges = 0;          // edges cut
  double length = 0;      // their total length, model units
  std::string note;       // what was cut, for the log; empty when the piece was a disk already
};

// Cuts piece (V, F and the vertex map updated: a cut vertex gets one copy per side) into a
// disk. Throws qd::common::Error if the result is no disk (a piece with non-manifold edges left).
DiskCut cut_to_disk(Piece& piece);

}  // namespace qd::flatten
