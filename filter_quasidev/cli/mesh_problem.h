// The bridge between the command's mesh tables and the approximation engine.
// make_problem: MeshFile + ApproximateOptions -> qd::Problem (positions, triangles, patch ids
//   unless --no-use-patches, constrained vertices from the file's selection and the
//   --constraints-file, parameters with the tolerances in model units: params::engine_params).
// output_fields: qd::Result + ApproximateOptions -> the new positions, the chosen per-vertex
//   quality (K after or displacement) and its colour ramp over the robust (2nd–98th percentile)
//   range.
// Throws qd::Error (degenerate mesh, bad constraint file, wrong result sizes) or UsageError
// (--patch-tolerance-ae for a patch the mesh does not have).
#pragma once

#include "approximate/problem.h"
#include "approximate/result.h"
#include "io/mesh_file.h"
#include "io/output_mesh.h"
#include "options.h"

namespace qd::cli {

Problem make_problem(const meshio::MeshFile& mesh, const ApproximateOptions& options);

meshio::OutputFields output_fields(const Result& result, const ApproximateOptions& options,
                                   std::size_t vertex_count);

}  // namespace qd::cli
