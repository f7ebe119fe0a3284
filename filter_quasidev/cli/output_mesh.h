// Builds the PLY tables of the command's output from the input mesh and the engine's result.
// Inputs: the MeshFile as read, the new positions (same vertex order), per-vertex quality
// (empty = none written) and colours (empty = keep the input's colours, if any), per-face
// quality and colours (each empty = none written, the input's own kept).
// Output: a PlyFile with
//   vertex: x y z as double (whatever the input's type, so no precision is lost), every other
//           input vertex property unchanged (nx ny nz, if present, recomputed from the new
//           positions), then `quality` (double) and `red green blue alpha` (uchar), which replace
//           the input's own;
//   face:   vertex_indices (list uchar int), then every input face property unchanged except
//           those the fields replace, then `quality` (double) and `red green blue alpha`
//           (uchar) when given;
//   every other input element, comment and obj_info line unchanged.
#pragma once

#include <array>
#include <vector>

#include "mesh_file.h"
#include "ply_file.h"

namespace qd::meshio {

struct OutputFields {
  std::vector<std::array<double, 3>> positions;
  std::vector<double> quality;
  std::vector<std::array<unsigned char, 3>> colors;
  std::vector<double> face_quality;
  std::vector<std::array<unsigned char, 3>> face_colors;
};

PlyFile output_ply(const MeshFile& mesh, const OutputFields& fields);

}  // namespace qd::meshio
