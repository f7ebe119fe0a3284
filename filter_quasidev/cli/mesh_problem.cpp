#include "mesh_problem.h"

#include <cmath>
#include <string>

#include "io/constraint_file.h"
#include "mesh_geometry.h"

namespace qd::cli {

approximate::Problem make_problem(const io::MeshDocument& mesh, const ApproximateOptions& o) {
  approximate::Problem problem;
  set_geometry(mesh, problem);
  if (!o.settings.use_patches) problem.patch.clear();
  problem.constrained = mesh.constrained;
  if (!o.settings.constraints_file.empty()) {
    problem.constrained.resize(mesh.positions.size(), 0);
    for (std::size_t v :
         io::read_constraint_file(o.settings.constraints_file, mesh.positions.size()))
      problem.constrained[v] = 1;
  }
  const double ae = common::average_edge_length(problem.V, problem.F);
  if (!(ae > 0) || !std::isfinite(ae))
    throw common::Error("the mesh's average edge length is " + std::to_string(ae) +
                        " (all vertices coincide?); nothing to approximate");
  try {
    problem.params = params::engine_params(o.settings, ae, problem.patch);
  } catch (const params::ParamError& e) {
    throw UsageError("--patch-tolerance-ae " + std::string(e.what()));
  }
  return problem;
}

}  // namespace qd::cli
