// Reads a constraint file: one vertex index (0-based, as in the mesh file) per line; blank lines
// and text after '#' are ignored. Input: the path and the mesh's vertex count. Output: the
// indices in file order (duplicates allowed). Throws qd::common::Error "constraints 'FILE' line N:
// ..." for a token that is not an index or an index out of range.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace qd::io {

std::vector<std::size_t> read_constraint_file(const std::string& path, std::size_t vertex_count);

}  // namespace qd::io
