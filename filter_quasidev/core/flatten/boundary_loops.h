// The boundary loops of a mesh: closed chains of edges that only one face uses.
#pragma once

#include <vector>

#include "common/mesh.h"
#include "flatten/common_names.h"
#include "flatten/edge_table.h"

namespace qd::flatten {

// Each loop as its vertices in the order the faces run along it, so the faces lie to the left
// of a loop (a disk's boundary turns counter-clockwise in an orientation-preserving layout).
// Loops are found in the order of their first boundary edge; each starts at that edge.
std::vector<std::vector<int>> boundary_loops(const Triangles& F, const EdgeTable& edges);

// Euler characteristic V − E + F of the mesh (every vertex in [0, vertex_count) is used).
int euler_characteristic(const Triangles& F, const EdgeTable& edges, int vertex_count);

}  // namespace qd::flatten
