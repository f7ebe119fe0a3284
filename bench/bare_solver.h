// The floor the engine is measured against: for each solve group of a problem (one per patch
// with fixed seams, as the engine forms them), the same matrix M (Eq. 17, initial targets)
// factorised from scratch, factorised again numerically and solved once, with nothing else
// around it.
#pragma once

#include <vector>

#include "approximate/problem.h"

namespace qd::bench {

using namespace qd::approximate;
using namespace qd::common;

struct BareGroup {
  int patch = 0;  // patch id (-1 for the joint group of free seams)
  long unknowns = 0;
  double factor_ms = 0;    // symbolic analysis + numeric factorisation, median
  double refactor_ms = 0;  // a further numeric factorisation (the analysis reused), median
  double solve_ms = 0;     // one forward + back substitution, median
};

std::vector<BareGroup> bare_solver_times(const Problem& problem, int runs);

}  // namespace qd::bench
