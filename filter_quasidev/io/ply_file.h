// A PLY file as tables: its format, its elements (in file order) and its header remarks.
// Inputs/outputs of parse_ply (ply_reader.h) and serialize_ply (ply_writer.h).
#pragma once

#include <string>
#include <vector>

#include "io/mesh_file.h"

namespace qd::meshio {

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyFile {
  PlyFormat format = PlyFormat::BinaryLittleEndian;
  std::vector<PlyElement> elements;
  std::vector<std::string> comments;
  std::vector<std::string> obj_info;

  // Pointer to the element called `name`, or nullptr.
  const PlyElement* find(const std::string& element_name) const;
};

}  // namespace qd::meshio
