#include "flatten_fields.h"

#include <string>

#include "flatten/stretch_ramp.h"
#include "mesh_geometry.h"

namespace qd::cli {

FlattenProblem make_flatten_problem(const meshio::MeshFile& mesh, const FlattenOptions& o) {
  FlattenProblem problem;
  set_geometry(mesh, problem);
  problem.patch_names = mesh.patch_names;
  problem.params = o.settings.engine;
  return problem;
}

meshio::OutputFields flatten_output_fields(const FlattenResult& result, std::size_t face_count) {
  if (static_cast<std::size_t>(result.uv.rows()) != face_count ||
      result.stretch.size() != face_count)
    throw Error("internal error: the flattening returned " + std::to_string(result.uv.rows()) +
                " texture coordinate rows and " + std::to_string(result.stretch.size()) +
                " stretch values for " + std::to_string(face_count) + " faces");
  meshio::OutputFields fields;
  fields.texcoords.resize(face_count);
  for (std::size_t f = 0; f < face_count; ++f)
    for (int k = 0; k < 6; ++k)
      fields.texcoords[f][static_cast<std::size_t>(k)] = result.uv(static_cast<Eigen::Index>(f), k);
  fields.face_quality = result.stretch;
  const QualityRange range = stretch_ramp_range(result.stretch);
  fields.face_colors.reserve(face_count);
  for (double s : result.stretch) fields.face_colors.push_back(ramp_color(s, range));
  return fields;
}

}  // namespace qd::cli
