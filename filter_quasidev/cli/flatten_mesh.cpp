#include "flatten_mesh.h"

#include "mesh_geometry.h"

namespace qd::cli {

FlattenProblem make_flatten_problem(const meshio::MeshDocument& mesh, const FlattenOptions& o) {
  FlattenProblem problem;
  set_geometry(mesh, problem);
  problem.patch_names = mesh.patch_names;
  problem.params = o.settings.engine;
  return problem;
}

}  // namespace qd::cli
