// Which patches are solved together (beyond the paper). A patch most of whose vertices lie on
// seams or the open boundary (fewer interior vertices than others: a small or thin panel) has
// little that can move while its seams are held, and with fixed seams its curvature and that
// of its neighbours' seams stays where it is. Such a patch joins the neighbouring solve group
// with which it shares most vertices, across edges oriented alike on both sides, and the
// seams inside a group are free like its other vertices; repeated until no group is left that
// is mostly seam. The patch ids the user gave stay as they are in the output and the report.
// On the shared shirt re-cut into 50 panels, fixed seams then removed 49 % of G_ABD instead of
// 24 % (the shirt's own 5 panels: 72 %); docs/robustness.md.
#pragma once

#include <vector>

#include "common/mesh.h"

namespace qd {

struct PatchMerge {
  int patch = 0;   // a patch id
  int faces = 0;
  int group = 0;   // the patch id of the group it is solved in
};

struct SolveGroups {
  std::vector<int> group;          // per face: its solve group (a patch id of the group)
  std::vector<PatchMerge> merged;  // the patches solved in another's group, by patch id
};

// patch: patch id per face (one per face); boundary: per vertex, on an open boundary edge.
SolveGroups solve_groups(const Triangles& F, const std::vector<int>& patch,
                         const std::vector<char>& boundary);

}  // namespace qd
