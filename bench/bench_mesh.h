// Generated benchmark meshes: a gently curved sheet (a quarter of a cylinder, radius 1, with
// smooth bumps of 0.3 average edge lengths along the normal) on a regular grid, split into
// horizontal bands (each a bumpy cylinder band) that are the patches. Near-developable, as the method expects.
#pragma once

#include "mesh_file.h"

namespace qd::bench {

// About `triangles` triangles (2·columns·rows, aspect 1:1), split into `patches` bands.
meshio::MeshFile curved_sheet(long triangles, int patches);

}  // namespace qd::bench
