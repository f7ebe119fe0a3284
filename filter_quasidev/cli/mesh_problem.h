// The bridge between the command's mesh tables and the approximation engine.
// make_problem: MeshDocument + ApproximateOptions -> qd::approximate::Problem (positions,
// triangles, patch ids
//   unless --no-use-patches, constrained vertices from the file's selection and the
//   --constraints-file, parameters with the tolerances in model units: params::engine_params).
// Throws qd::common::Error (degenerate mesh, bad constraint file) or UsageError
// (--patch-tolerance-ae for a patch the mesh does not have).
#pragma once

#include "approximate/problem.h"
#include "io/mesh_document.h"
#include "options.h"

namespace qd::cli {

approximate::Problem make_problem(const io::MeshDocument& mesh, const ApproximateOptions& options);

}  // namespace qd::cli
