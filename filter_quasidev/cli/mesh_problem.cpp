#include "mesh_problem.h"

#include <string>

#include "approximate_problem.h"
#include "io/constraint_file.h"
#include "mesh_geometry.h"

namespace qd::cli {

approximate::Problem make_problem(const io::MeshDocument& mesh, const ApproximateOptions& o) {
  std::vector<char> constrained = mesh.constrained;
  if (!o.settings.constraints_file.empty()) {
    constrained.resize(mesh.positions.size(), 0);
    for (std::size_t v :
         io::read_constraint_file(o.settings.constraints_file, mesh.positions.size()))
      constrained[v] = 1;
  }
  try {
    return frontend::approximate_problem(positions_of(mesh), triangles_of(mesh), mesh.patch,
                                         std::move(constrained), o.settings);
  } catch (const params::ParamError& e) {
    throw UsageError("--patch-tolerance-ae " + std::string(e.what()));
  }
}

}  // namespace qd::cli
