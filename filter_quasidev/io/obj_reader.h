// Wavefront OBJ reader for the command.
// Input: the file's bytes. Output: a MeshDocument with positions (`v`, extra values such as colours
// ignored), triangles (`f` with v, v/vt, v//vn or v/vt/vn corners, negative = relative indices;
// polygons fan-triangulated), per-corner `texcoord` (2 floats per corner, from `vt`) when every
// face has texture coordinates, and patch ids from `g` / `o` groups numbered 0, 1, ... in order
// of first appearance (faces before any group form their own group), each named by its group's
// name (the words after `g` / `o`; the unnamed group has none). No patch ids without groups.
// Normals, materials, lines and points are ignored (a note says so). Throws qd::common::Error "OBJ
// line N:
// ..." on malformed or out-of-range data.
#pragma once

#include <string_view>

#include "io/mesh_document.h"

namespace qd::io {

MeshDocument parse_obj(std::string_view bytes);

}  // namespace qd::io
