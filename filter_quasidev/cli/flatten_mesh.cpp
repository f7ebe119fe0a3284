#include "flatten_mesh.h"

#include "mesh_geometry.h"

namespace qd::cli {

flatten::FlattenProblem make_flatten_problem(const io::MeshDocument& mesh,
                                             const FlattenOptions& o) {
  flatten::FlattenProblem problem;
  set_geometry(mesh, problem);
  problem.patch_names = mesh.patch_names;
  problem.params = o.settings.engine;
  return problem;
}

}  // namespace qd::cli
