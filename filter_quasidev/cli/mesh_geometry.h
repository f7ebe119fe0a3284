// The engine's view of a mesh file's geometry: positions and triangles, as every job needs them.
#pragma once

#include "common/mesh.h"
#include "mesh_file.h"

namespace qd::cli {

Positions positions_of(const meshio::MeshFile& mesh);
Triangles triangles_of(const meshio::MeshFile& mesh);

}  // namespace qd::cli
