// The engine's view of a mesh file: positions, triangles and patch ids, as every job's problem
// (qd::approximate::Problem, qd::flatten::FlattenProblem) holds them.
#pragma once

#include "common/mesh.h"
#include "io/mesh_document.h"

namespace qd::cli {

common::Positions positions_of(const io::MeshDocument& mesh);
common::Triangles triangles_of(const io::MeshDocument& mesh);

// Sets problem.V, problem.F and problem.patch from the mesh.
template <typename Problem>
void set_geometry(const io::MeshDocument& mesh, Problem& problem) {
  problem.V = positions_of(mesh);
  problem.F = triangles_of(mesh);
  problem.patch = mesh.patch;
}

}  // namespace qd::cli
