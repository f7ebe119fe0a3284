// Generated benchmark meshes: a gently curved sheet (a quarter of a cylinder, radius 1, with
// smooth bumps of 0.3 average edge lengths along the normal) on a regular grid, split into
// horizontal bands (each a bumpy cylinder band) that are the patches. Near-developable, as the
// method expects.
#pragma once

#include "io/mesh_document.h"

namespace qd::bench {

// About `triangles` triangles (2·columns·rows, aspect 1:1), split into `patches` bands.
io::MeshDocument curved_sheet(long triangles, int patches);

// A closed tube (a cylinder of radius 1 and height 2π, open at both ends, no seam) of about
// `triangles` triangles, every vertex moved along the radius by a pseudo-random 0.1 average
// edge lengths (the same for every call): the noisy tube of issue 11, one patch.
io::MeshDocument noisy_tube(long triangles);

// A closed torus (radii 2 and 1, no seam) of about `triangles` triangles on a regular grid,
// twice as many columns around the axis as around the tube: doubly curved everywhere, the
// segmentation's benchmark (no patch ids).
io::MeshDocument torus(long triangles);

}  // namespace qd::bench
