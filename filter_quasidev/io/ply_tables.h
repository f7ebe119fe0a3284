// A PLY file as tables: its format, its elements (in file order) and its header remarks. The PLY
// codec's own form (parse_ply_tables in ply_reader.h, serialize_ply_tables in ply_writer.h), used
// by the document's PLY reader (ply_mesh.h) and writer (output_mesh.h); the command and the jobs
// see only the document (mesh_document.h).
#pragma once

#include <string>
#include <vector>

#include "io/mesh_document.h"

namespace qd::io {

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyTables {
  PlyFormat format = PlyFormat::BinaryLittleEndian;
  std::vector<PlyElement> elements;
  std::vector<std::string> comments;
  std::vector<std::string> obj_info;

  // Pointer to the element called `name`, or nullptr.
  const PlyElement* find(const std::string& element_name) const;
};

}  // namespace qd::io
