// The engine's view of a mesh file: positions, triangles and patch ids, as every job's problem
// (qd::Problem, qd::FlattenProblem) holds them.
#pragma once

#include "common/mesh.h"
#include "io/mesh_document.h"

namespace qd::cli {

Positions positions_of(const meshio::MeshDocument& mesh);
Triangles triangles_of(const meshio::MeshDocument& mesh);

// Sets problem.V, problem.F and problem.patch from the mesh.
template <typename Problem>
void set_geometry(const meshio::MeshDocument& mesh, Problem& problem) {
  problem.V = positions_of(mesh);
  problem.F = triangles_of(mesh);
  problem.patch = mesh.patch;
}

}  // namespace qd::cli
