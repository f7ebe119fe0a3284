// Which patches are solved together (beyond the paper). A patch whose seams, held, would keep
// most of what it has joins the neighbouring solve group with which it shares most vertices,
// and the seam between them is solved like the group's other vertices, so it moves, with fixed
// seams too (the log names each join):
//  - always, a patch most of whose vertices lie on seams or the open boundary (fewer interior
//    vertices than others: a small or thin panel, or one of fewer than kMinPatchFaces faces, too
//    few to fit): with its seams held, little or nothing of it can move;
//  - given the curvature, also a patch with more |K| on its seam vertices than inside: its
//    seams would hold most of its curvature. This join is measured, not assumed
//    (quasidev.cpp): the mesh is solved both ways and the one that removes more is kept, since
//    on a CAD part the curvature on seams is at creases that no move removes (fandisk: 0.8 %
//    removed joined, 14.9 % held), while on a garment re-cut into 50 panels the joins take the
//    share of its own panels' reduction from 62 % to 89 % (docs/many_panels.md).
// Joins go across edges oriented alike on both sides only, and repeat until no group qualifies.
// The patch ids the user gave stay as they are in the output and the report.
#pragma once

#include <vector>

#include "approximate/common_names.h"
#include "approximate/result.h"
#include "common/mesh.h"

namespace qd::approximate {

struct SolveGroups {
  std::vector<int> group;        // per face: its solve group (a patch id of the group)
  std::vector<PatchJoin> joins;  // the patches solved in another's group, by patch id
};

// The groups by the first rule alone, every other seam held, and by both rules: the two ways
// quasidev.cpp solves a mesh and compares.
struct SolveGroupings {
  SolveGroups held;
  SolveGroups joined;
};

// patch: patch id per face (one per face); boundary: per vertex, on an open boundary edge;
// curvature: per vertex, |K| of the input (Eq. 18), or empty for the first rule alone (then
// joined is held). The mesh's edges are looked up once for both.
SolveGroupings solve_groups(const Triangles& F, const std::vector<int>& patch,
                            const std::vector<char>& boundary,
                            const std::vector<double>& curvature);

}  // namespace qd::approximate
