// Which patches are solved together (beyond the paper). With fixed seams, a patch of fewer
// than kMinPatchFaces faces (too few to fit, and every vertex on its seam) would stay as it is;
// it joins the neighbouring solve group with which it shares most vertices, and the seam
// between them moves (the log names each). With free seams, every patch most of whose vertices
// lie on seams or the open boundary (fewer interior vertices than others: a small or thin
// panel) joins its neighbour the same way, so the seams inside a group get angle-defect rows
// like its other vertices; on the shared shirt re-cut into 50 panels free seams then removed
// 66 % of G_ABD instead of 41 % (its own 5 panels: 81 %; docs/robustness.md). Joins go across
// edges oriented alike on both sides only, and repeat until no group qualifies. The patch ids
// the user gave stay as they are in the output and the report.
#pragma once

#include <vector>

#include "approximate/common_names.h"
#include "common/mesh.h"

namespace qd::approximate {

struct PatchMerge {
  int patch = 0;  // a patch id
  int faces = 0;
  int group = 0;  // the patch id of the group it is solved in
};

struct SolveGroups {
  std::vector<int> group;          // per face: its solve group (a patch id of the group)
  std::vector<PatchMerge> merged;  // the patches solved in another's group, by patch id
};

// patch: patch id per face (one per face); boundary: per vertex, on an open boundary edge;
// mostly_seam: join every patch mostly on seams (free seams), else only those too small to fit.
SolveGroups solve_groups(const Triangles& F, const std::vector<int>& patch,
                         const std::vector<char>& boundary, bool mostly_seam);

}  // namespace qd::approximate
