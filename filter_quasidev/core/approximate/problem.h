// Input of the engine: one mesh, its patches, its constrained vertices, the parameters.
#pragma once

#include <vector>

#include "approximate/common_names.h"
#include "approximate/params.h"
#include "common/mesh.h"

namespace qd::approximate {

struct Problem {
  Positions V;
  Triangles F;
  std::vector<int> patch;         // patch id per face; empty = the whole mesh is one patch 0
  std::vector<char> constrained;  // per vertex, 1 = must not move; empty = none selected
  Params params;
};

}  // namespace qd::approximate
