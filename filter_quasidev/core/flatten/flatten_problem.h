// Input of the flattening (docs/design.md "Beyond the paper": flatten): one mesh, its patches and
// the parameters. Each patch becomes one pattern piece per edge-connected component.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "common/mesh.h"
#include "common/solver_kind.h"
#include "flatten/common_names.h"

namespace qd::flatten {

struct FlattenParams {
  int max_iterations = 100;  // ARAP iterations per piece at most (arap.h)
  double tolerance = 1e-4;   // ARAP stops when the energy changes by less than this, relatively
  double gap = 0;            // space between pieces on the sheet, model units; 0 = automatic
  double notch_spacing = 0;  // notches along a seam this far apart (notches.h), model units;
                             // 0 = an eighth of the largest piece's longer side
  double seam_allowance =
      0;  // cut line this far outside the sew line (seam_allowance.h), model units
  Eigen::Vector3d grain_up =
      Eigen::Vector3d::UnitY();   // 3D direction the grainlines follow (grainline.h)
  double symmetry_tolerance = 1;  // percent of a piece's size: congruent or mirror pieces within
                                  // it are cut from one (symmetric_pieces.h); 0 = never grouped
  SolverKind solver = SolverKind::Auto;  // sparse Cholesky back end (positive_definite_factor.h)
  int threads = 0;                       // pieces flattened at once; 0 = all cores
};

struct FlattenProblem {
  Positions V;
  Triangles F;
  std::vector<int> patch;  // patch id per face; empty = the whole mesh is one patch 0
  std::map<int, std::string> patch_names;  // panel names of the input, by patch id; may be empty
  FlattenParams params;
};

}  // namespace qd::flatten
