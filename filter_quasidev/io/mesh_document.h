// The document: a mesh file in memory, the one form the readers (PLY, OBJ, OFF) produce, the
// command turns into the engine's problem, a job copies and changes (output_mesh.h) and the
// writer writes. Its mesh part is what the engine uses; its PlyElement tables (one column per
// property) carry every property and element the engine does not use from input to output.
// Each column holds its values in the property's own PLY type (scalar_column.h).
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "io/scalar_column.h"

namespace qd::io {

// One property of an element: a scalar column, or a list column (values of element i are
// values[offsets[i] .. offsets[i+1]) ).
struct PlyProperty {
  std::string name;
  bool is_list = false;
  ScalarType count_type = ScalarType::UInt8;  // lists only
  ScalarColumn values;
  std::vector<std::size_t> offsets;  // lists only, size count + 1

  ScalarType type() const { return values.type(); }
  std::size_t list_size(std::size_t i) const { return offsets[i + 1] - offsets[i]; }
};

// A scalar column called `name` of the given type holding `values`.
PlyProperty scalar_property(const std::string& name, ScalarType type,
                            const std::vector<double>& values);

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;

  // Index of the property called `name`, or -1.
  int find(const std::string& property_name) const;
};

// A mesh as the command uses it: triangles, optional patch ids and constraints, and everything
// else from the file kept for pass-through.
struct MeshDocument {
  std::vector<std::array<double, 3>> positions;
  std::array<ScalarType, 3> position_types = {ScalarType::Float64, ScalarType::Float64,
                                              ScalarType::Float64};  // of x, y, z in the file
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> patch;                  // per triangle; empty = the file has no patch ids
  std::map<int, std::string> patch_names;  // panel names by patch id (OBJ groups, PLY comments)
  std::vector<char> constrained;           // per vertex; empty = the file selects no vertex
  // Per triangle, u v of its three corners from an OBJ file's `vt` (empty = none); written as the
  // face `texcoord` list, ahead of the face's other properties.
  std::vector<std::array<double, 6>> corner_uv;
  // Vertex properties other than x, y, z (one value per vertex, or lists).
  std::vector<PlyProperty> vertex_extra;
  // Face properties other than the index list (one entry per output triangle: a polygon's
  // scalars are repeated on each of its triangles; per-corner lists are split per triangle).
  std::vector<PlyProperty> face_extra;
  std::vector<PlyElement> other_elements;  // elements other than vertex and face, as read
  std::vector<std::string> comments;       // PLY "comment" lines
  std::vector<std::string> obj_info;       // PLY "obj_info" lines
  std::vector<std::string> notes;          // remarks for the user (e.g. polygons triangulated)
};

}  // namespace qd::io
