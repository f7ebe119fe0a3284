// Input of the flattening (docs/design.md "Beyond the paper": flatten): one mesh, its patches and
// the parameters. Each patch becomes one pattern piece per edge-connected component.
#pragma once

#include <vector>

#include "common/mesh.h"
#include "common/sparse_cholesky.h"

namespace qd {

struct FlattenParams {
  int max_iterations = 100;   // ARAP iterations per piece at most (arap.h)
  double tolerance = 1e-4;    // ARAP stops when the energy changes by less than this, relatively
  double gap = 0;             // space between pieces on the sheet, model units; 0 = automatic
  double notch_spacing = 0;   // notches along a seam this far apart (notches.h), model units;
                              // 0 = an eighth of the largest piece's longer side
  SolverKind solver = SolverKind::Auto;  // sparse Cholesky back end (sparse_cholesky.h)
  int threads = 0;            // pieces flattened at once; 0 = all cores
};

struct FlattenProblem {
  Positions V;
  Triangles F;
  std::vector<int> patch;  // patch id per face; empty = the whole mesh is one patch 0
  FlattenParams params;
};

}  // namespace qd
