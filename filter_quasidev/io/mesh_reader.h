// Reads a mesh file for the command: PLY, OBJ or OFF, chosen by the file's first bytes ("ply",
// "OFF") or else by its extension (.obj). Input: a path. Output: a MeshDocument with at least one
// triangle. Throws qd::common::Error naming the file and what was wrong (missing, unreadable,
// empty, unknown format, malformed, no faces).
#pragma once

#include <string>

#include "io/mesh_document.h"

namespace qd::io {

// The whole content of a file; throws qd::common::Error if it cannot be read.
std::string read_file_bytes(const std::string& path);

MeshDocument read_mesh(const std::string& path);

}  // namespace qd::io
