// Turns polygon faces into triangles for the engine, keeping every face property.
// Inputs: the faces' vertex index lists (a list column), the number of vertices, the faces'
// other columns. Outputs (into `mesh`): triangles, face_extra with one entry per triangle
// (a polygon's scalars repeated; a per-corner list, i.e. one whose length is a multiple of the
// corner count, split to the triangle's corners; any other list repeated), and a note when
// polygons were fan-triangulated. Returns, per triangle, the index of the face it came from.
// Throws qd::common::Error for a face with fewer than 3 corners or an index out of range.
#pragma once

#include <cstddef>
#include <vector>

#include "io/mesh_document.h"

namespace qd::io {

std::vector<std::size_t> add_faces(const PlyProperty& indices, std::size_t face_count,
                                   std::size_t vertex_count,
                                   const std::vector<PlyProperty>& face_columns,
                                   MeshDocument& mesh);

}  // namespace qd::io
