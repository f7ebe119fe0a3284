// Reads a PLY file into the document the command works on: it reads the file as tables
// (ply_reader.h) and moves their columns into the document. Input: the file's bytes. Output: a
// MeshDocument with positions (vertex x, y, z), triangles (face vertex_indices or vertex_index,
// polygons fan-triangulated), patch ids (face `quality` rounded, else an integer face `patch`),
// panel names from comments `comment patch <id> <name…>` (the name is the rest of the line; other
// comments, and these too, are kept as they are), constrained vertices (vertex `flags` bit 0x20,
// MeshLab's selection) and every other property and element kept for pass-through. Throws
// qd::common::Error when the vertex or face element or a coordinate is missing or unusable.
#pragma once

#include <string_view>

#include "io/mesh_document.h"

namespace qd::io {

// vcg's selection bit in the PLY vertex `flags` property.
constexpr int kSelectedFlag = 0x20;

// Whether a `flags` value, read as a double from any PLY type, has the selection bit. NaN and
// magnitudes of 2^58 or more have none: doubles there are multiples of 64.
bool has_selected_flag(double flags);

MeshDocument parse_ply(std::string_view bytes);

}  // namespace qd::io
