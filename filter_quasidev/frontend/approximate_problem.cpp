#include "approximate_problem.h"

#include <cmath>
#include <string>
#include <utility>

#include "common/mesh.h"

namespace qd::frontend {

approximate::Problem approximate_problem(common::Positions V, common::Triangles F,
                                         std::vector<int> patch, std::vector<char> constrained,
                                         const params::ApproximateSettings& settings) {
  approximate::Problem problem;
  problem.V = std::move(V);
  problem.F = std::move(F);
  if (settings.use_patches) problem.patch = std::move(patch);
  problem.constrained = std::move(constrained);
  const double ae = common::average_edge_length(problem.V, problem.F);
  if (!(ae > 0) || !std::isfinite(ae))
    throw common::Error("the mesh's average edge length is " + std::to_string(ae) +
                        " (all vertices coincide?); nothing to approximate");
  problem.params = params::engine_params(settings, ae, problem.patch);
  return problem;
}

}  // namespace qd::frontend
