// The bridge between the command's mesh tables and the flattening engine.
// make_flatten_problem: MeshFile + FlattenOptions -> qd::FlattenProblem (positions, triangles,
//   patch ids, panel names, parameters as given: the flattening's lengths are in model units).
// flatten_output_fields: qd::FlattenResult -> the fields `quasidev flatten` writes: per face
//   the wedge texture coordinates (model units), quality = signed stretch and its colour ramp
//   (flatten/stretch_ramp.h); the vertices keep their positions. Throws qd::Error when the
//   result does not have one entry per face.
#pragma once

#include "flatten/flatten_problem.h"
#include "flatten/flatten_result.h"
#include "io/mesh_file.h"
#include "io/output_mesh.h"
#include "options.h"

namespace qd::cli {

FlattenProblem make_flatten_problem(const meshio::MeshFile& mesh, const FlattenOptions& options);

meshio::OutputFields flatten_output_fields(const FlattenResult& result, std::size_t face_count);

}  // namespace qd::cli
