// The command's output document and its PLY bytes. A job copies the input document and the setters
// below put its columns in it:
//   set_positions: the positions, written as double (whatever the input's type, so no precision
//     is lost), and the vertex nx ny nz (if present) recomputed from them;
//   set_quality: `quality` (double), replacing the element's own;
//   set_colors: `red green blue alpha` (uchar, alpha 255), replacing the element's own;
//   set_texcoords: face `texcoord` (list uchar float: u0 v0 u1 v1 u2 v2, the type MeshLab reads),
//     replacing the input's own (an OBJ file's corner_uv or a PLY texcoord).
// Replaced columns are removed and the new ones appended, so the order is the input's, then
// texcoord, quality, colours in the order set. Throws qd::common::Error when a column does not have
// one value per vertex (per face). serialize_ply writes a document: vertex x y z (position_types)
// then vertex_extra; face vertex_indices (list uchar int), the corner_uv as `texcoord` (list uchar
// float), then face_extra; every other element, comment and obj_info line.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "common/mesh.h"
#include "flatten/flatten_result.h"
#include "io/mesh_document.h"
#include "io/ply_tables.h"

namespace qd::io {

enum class Element { Vertex, Face };

void set_positions(MeshDocument& doc, const common::Positions& V);
void set_quality(MeshDocument& doc, Element element, const std::vector<double>& quality);
void set_colors(MeshDocument& doc, Element element,
                const std::vector<std::array<unsigned char, 3>>& colors);
void set_texcoords(MeshDocument& doc, const flatten::WedgeUV& uv);

std::string serialize_ply(const MeshDocument& doc, PlyFormat format);

}  // namespace qd::io
