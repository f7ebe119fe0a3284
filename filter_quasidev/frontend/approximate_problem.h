// The approximation's problem from a mesh's arrays and the user's settings, as every front end
// that runs it from tables builds it (the command, the Python module): patch ids unless
// use_patches is off, the constrained vertices as given, the engine's parameters with the
// tolerances in model units (params::engine_params). Throws qd::common::Error for a mesh whose
// average edge length is not above 0, and params::ParamError when patch_tolerance_ae names a
// patch the mesh does not have.
#pragma once

#include <vector>

#include "approximate/problem.h"
#include "approximate_settings.h"

namespace qd::frontend {

approximate::Problem approximate_problem(common::Positions V, common::Triangles F,
                                         std::vector<int> patch, std::vector<char> constrained,
                                         const params::ApproximateSettings& settings);

}  // namespace qd::frontend
