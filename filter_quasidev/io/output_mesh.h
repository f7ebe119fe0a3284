// Builds the PLY tables of the command's output from the input mesh and the engine's result.
// Inputs: the MeshFile as read and the fields a job writes: per vertex the new positions (same
// vertex order; empty = the input's, kept with their types, normals untouched), quality and
// colours; per triangle wedge texture coordinates, quality and colours (each empty = none
// written, the input's own kept).
// Output: a PlyFile with
//   vertex: x y z (as double when moved, whatever the input's type, so no precision is lost),
//           every other input vertex property unchanged (nx ny nz, if present, recomputed from
//           moved positions), then `quality` (double) and `red green blue alpha` (uchar) when
//           given, which replace the input's own;
//   face:   vertex_indices (list uchar int), every input face property unchanged except those
//           the fields replace, then `texcoord` (list uchar float: u0 v0 u1 v1 u2 v2, the type
//           MeshLab reads), `quality` (double) and `red green blue alpha` (uchar) when given;
//   every other input element, comment and obj_info line unchanged.
#pragma once

#include <array>
#include <vector>

#include "io/mesh_file.h"
#include "io/ply_file.h"

namespace qd::meshio {

struct OutputFields {
  std::vector<std::array<double, 3>> positions;
  std::vector<double> quality;
  std::vector<std::array<unsigned char, 3>> colors;
  std::vector<std::array<double, 6>> texcoords;
  std::vector<double> face_quality;
  std::vector<std::array<unsigned char, 3>> face_colors;
};

PlyFile output_ply(const MeshFile& mesh, const OutputFields& fields);

}  // namespace qd::meshio
