// Helpers of the reader/writer tests: building small PLY tables and parsing bytes to a mesh.
#pragma once

#include <string>
#include <vector>

#include "io/mesh_document.h"
#include "io/ply_tables.h"

namespace qd::io::test {

PlyProperty list(const std::string& name, ScalarType count_type, ScalarType type,
                 const std::vector<std::vector<double>>& lists);

// A unit square made of two triangles plus one quad (5 vertices), with a per-corner texcoord
// list, a face quality (patch id), vertex flags (vertex 4 selected) and an extra "edge" element.
PlyTables sample_ply();

// The document of a PLY file's bytes (parse_ply).
MeshDocument mesh_of(const std::string& bytes);

// The message of the qd::common::Error that `f` throws ("" if it throws none).
template <typename F>
std::string error_of(F f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace qd::io::test
