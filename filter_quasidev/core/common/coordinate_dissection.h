// Nested dissection of a mesh's vertex graph by its vertices' coordinates (issue 28), the sets
// that constrain a minimum-degree order of the graph (vertex_order.h: CHOLMOD's CAMD orders each
// set after the sets before it). Each part of the graph is cut into halves at the median of its
// points along x, y or z, whichever axis needs the fewest separating nodes: those of one half
// that touch the other (the half with fewer such nodes gives them). The separator's set follows
// the sets of both halves.
//
// Why our own and not METIS's nested dissection (which CHOLMOD calls, FillOrder::LeastFill): on
// the 1M-face torus of the benchmark (500k vertices) METIS's order cut the preconditioner's
// factorisations from 123 to 39 GFlop, but took 1.8 s of the run on one thread, so that the run
// gained only 0.2–0.6 s, and lost 1.2 s on 1M-face cylinders where AMD already fills little.
// These cuts and CAMD take about 0.3 s there for 45 GFlop (docs/performance.md, stop 46).
#pragma once

#include <vector>

#include "common/block_pattern.h"
#include "common/mesh.h"

namespace qd::common {

// set[v] for each node v of `graph` (block_pattern.h: a node per block) at points[v]: parts of
// at most `leaf` nodes are not cut further. Sets are numbered from 0 so that each separator's
// set is larger than those of the parts it separates. Deterministic: ties are broken by index.
std::vector<int> coordinate_dissection(const BlockPattern& graph, const std::vector<Vec3>& points,
                                       int leaf);

}  // namespace qd::common
