// Where the pattern gets notches, the marks by which two pieces are matched along a seam (or
// the two sides of a cut). Chosen once per mesh vertex, so both sides of a seam get the same
// ones: a seam edge is a mesh edge on the boundary of two piece sides; seam edges form chains
// between junctions (vertices where other than two seam edges meet: seam ends and corners where
// three pieces meet) or closed loops (an armhole); each chain gets a notch at its ends and at
// every `spacing` of arc length along it (the nearest vertex; a closed loop starts at its
// lowest vertex index). A notch at every seam vertex would read as hatching, not as marks.
#pragma once

#include <array>
#include <vector>

#include "common/mesh.h"
#include "flatten/common_names.h"

namespace qd::flatten {

// boundary_edges: every boundary edge of every piece, as mesh vertex pairs (in any order and
// direction); V: the mesh's positions. Returns per mesh vertex 1 = notch.
std::vector<char> notch_vertices(const Positions& V, std::vector<std::array<int, 2>> boundary_edges,
                                 double spacing);

}  // namespace qd::flatten
