// The bridge between the command's mesh tables and the flattening engine.
// make_flatten_problem: MeshDocument + FlattenOptions -> qd::flatten::FlattenProblem (positions,
// triangles,
//   patch ids, panel names, parameters as given: the flattening's lengths are in model units).
#pragma once

#include "flatten/flatten_problem.h"
#include "io/mesh_document.h"
#include "options.h"

namespace qd::cli {

flatten::FlattenProblem make_flatten_problem(const io::MeshDocument& mesh,
                                             const FlattenOptions& options);

}  // namespace qd::cli
