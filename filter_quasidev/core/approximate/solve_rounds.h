// The order in which the solve groups of one pass run. Groups that move no common vertex are
// independent and run at once: they may share vertices that every group of the pass holds
// (seams held), since each moves only its own. Of two groups that move a common (free seam)
// vertex, the later one starts from the earlier one's result. Rounds are a greedy colouring of
// the groups' adjacency in group order, so the schedule, and the result, do not depend on the
// number of threads.
#pragma once

#include <vector>

#include "approximate/common_names.h"
#include "common/mesh.h"

namespace qd::approximate {

// groups: the faces of each group; held: per vertex, 1 = no group of the pass moves it.
// Returns rounds of group indices; every group is in exactly one round, and no two groups in
// one round share a vertex that is not held.
std::vector<std::vector<size_t>> solve_rounds(const std::vector<std::vector<int>>& groups,
                                              const Triangles& F, const std::vector<char>& held);

}  // namespace qd::approximate
