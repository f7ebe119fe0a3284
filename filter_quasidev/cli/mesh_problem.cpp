#include "mesh_problem.h"

#include <cmath>
#include <string>

#include "common/quality_range.h"
#include "io/constraint_file.h"
#include "mesh_geometry.h"

namespace qd::cli {

Problem make_problem(const meshio::MeshFile& mesh, const ApproximateOptions& o) {
  Problem problem;
  set_geometry(mesh, problem);
  if (!o.settings.use_patches) problem.patch.clear();
  problem.constrained = mesh.constrained;
  if (!o.settings.constraints_file.empty()) {
    problem.constrained.resize(mesh.positions.size(), 0);
    for (std::size_t v :
         meshio::read_constraint_file(o.settings.constraints_file, mesh.positions.size()))
      problem.constrained[v] = 1;
  }
  const double ae = average_edge_length(problem.V, problem.F);
  if (!(ae > 0) || !std::isfinite(ae))
    throw Error("the mesh's average edge length is " + std::to_string(ae) +
                " (all vertices coincide?); nothing to approximate");
  try {
    problem.params = params::engine_params(o.settings, ae, problem.patch);
  } catch (const params::ParamError& e) {
    throw UsageError("--patch-tolerance-ae " + std::string(e.what()));
  }
  return problem;
}

meshio::OutputFields output_fields(const Result& result, const ApproximateOptions& o,
                                   std::size_t vertex_count) {
  const std::vector<double>& q = o.settings.output_quality == params::QualityKind::Curvature
                                     ? result.k_after
                                     : result.displacement;
  if (static_cast<std::size_t>(result.V.rows()) != vertex_count || q.size() != vertex_count)
    throw Error("internal error: the engine returned " + std::to_string(result.V.rows()) +
                " positions and " + std::to_string(q.size()) + " quality values for " +
                std::to_string(vertex_count) + " vertices");
  meshio::OutputFields fields;
  fields.positions.resize(vertex_count);
  for (std::size_t i = 0; i < vertex_count; ++i)
    for (int k = 0; k < 3; ++k)
      fields.positions[i][static_cast<std::size_t>(k)] = result.V(static_cast<Eigen::Index>(i), k);
  fields.quality = q;
  if (o.settings.colorize) {
    const QualityRange range = robust_quality_range(q);
    fields.colors.reserve(vertex_count);
    for (double value : q) fields.colors.push_back(ramp_color(value, range));
  }
  return fields;
}

}  // namespace qd::cli
