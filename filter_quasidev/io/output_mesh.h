// The command's output document, built from the input's: output_ply gives the input's tables
// (vertex: x y z with their types and every other property; face: vertex_indices (list uchar
// int), `texcoord` (list uchar float) from the OBJ corner texture coordinates, then every other
// property; every other element, comment and obj_info line), and the setters below put a job's
// columns in it:
//   set_positions: x y z as double (whatever the input's type, so no precision is lost), nx ny nz
//     (if present) recomputed from them;
//   set_quality: `quality` (double), replacing the element's own;
//   set_colors: `red green blue alpha` (uchar, alpha 255), replacing the element's own;
//   set_texcoords: face `texcoord` (list uchar float: u0 v0 u1 v1 u2 v2, the type MeshLab reads),
//     replacing the input's own.
// Replaced columns are removed and the new ones appended, so the order is the input's, then
// texcoord, quality, colours in the order set. Throws qd::Error when a column does not have one
// value per vertex (per face).
#pragma once

#include <array>
#include <vector>

#include "common/mesh.h"
#include "flatten/flatten_result.h"
#include "io/mesh_file.h"
#include "io/ply_file.h"

namespace qd::meshio {

PlyFile output_ply(const MeshFile& mesh);

// The element called "vertex" or "face" of an output document.
PlyElement& output_element(PlyFile& ply, const char* name);

void set_positions(PlyFile& ply, const MeshFile& mesh, const Positions& V);
void set_quality(PlyElement& element, const std::vector<double>& quality);
void set_colors(PlyElement& element, const std::vector<std::array<unsigned char, 3>>& colors);
void set_texcoords(PlyElement& face, const WedgeUV& uv);

}  // namespace qd::meshio
