// The order in which solve groups run. Groups that share no vertex are independent and run at
// once; of two groups that share seam vertices, the later one starts from the earlier one's
// result, so its never-worse check measures the seam curvature both sides produce. Rounds are
// a greedy colouring of the groups' adjacency in group order, so the schedule, and the result,
// do not depend on the number of threads.
#pragma once

#include <vector>

#include "common/mesh.h"

namespace qd {

// groups: the faces of each group. Returns rounds of group indices; every group is in exactly
// one round, and no two groups in one round share a vertex.
std::vector<std::vector<size_t>> solve_rounds(const std::vector<std::vector<int>>& groups,
                                              const Triangles& F, Eigen::Index vertex_count);

}  // namespace qd
