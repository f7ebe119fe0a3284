#include "io/triangulate.h"

#include <cmath>
#include <string>

#include "common/error.h"

namespace qd::io {

namespace {

void check_face(const PlyProperty& indices, std::size_t f, std::size_t vertex_count) {
  const std::size_t n = indices.list_size(f);
  if (n < 3)
    throw common::Error("face " + std::to_string(f) + " has " + std::to_string(n) +
                        " vertices; a face needs at least 3");
  for (std::size_t k = indices.offsets[f]; k < indices.offsets[f + 1]; ++k) {
    const double v = indices.values[k];
    if (v != std::floor(v))
      throw common::Error("face " + std::to_string(f) + " has vertex index " + std::to_string(v) +
                          ", which is not a whole number");
    if (v < 0 || v >= static_cast<double>(vertex_count))
      throw common::Error("face " + std::to_string(f) + " uses vertex index " +
                          std::to_string(static_cast<long long>(v)) +
                          ", out of range (the file has " + std::to_string(vertex_count) +
                          " vertices)");
  }
}

// Appends face f's value of `column` for the triangle with corners (0, c1, c2) of an n-gon.
void append_triangle_value(const PlyProperty& column, std::size_t f, std::size_t n, std::size_t c1,
                           std::size_t c2, PlyProperty& out) {
  if (!column.is_list) {
    out.values.push_back(column.values[f]);
    return;
  }
  const std::size_t begin = column.offsets[f];
  const std::size_t length = column.list_size(f);
  if (n == 3 || length == 0 || length % n != 0) {
    for (std::size_t k = begin; k < begin + length; ++k) out.values.push_back(column.values[k]);
  } else {
    const std::size_t per_corner = length / n;
    for (std::size_t corner : {std::size_t{0}, c1, c2})
      for (std::size_t k = 0; k < per_corner; ++k)
        out.values.push_back(column.values[begin + corner * per_corner + k]);
  }
  out.offsets.push_back(out.values.size());
}

}  // namespace

std::vector<std::size_t> add_faces(const PlyProperty& indices, std::size_t face_count,
                                   std::size_t vertex_count,
                                   const std::vector<PlyProperty>& face_columns,
                                   MeshDocument& mesh) {
  std::vector<PlyProperty> out(face_columns.size());
  for (std::size_t c = 0; c < face_columns.size(); ++c) {
    out[c].name = face_columns[c].name;
    out[c].values = ScalarColumn(face_columns[c].type());
    out[c].is_list = face_columns[c].is_list;
    out[c].count_type = face_columns[c].count_type;
    if (out[c].is_list) out[c].offsets.assign(1, 0);
  }
  std::vector<std::size_t> source;
  std::size_t polygons = 0;
  for (std::size_t f = 0; f < face_count; ++f) {
    check_face(indices, f, vertex_count);
    const std::size_t n = indices.list_size(f);
    const auto corner = [&indices, f](std::size_t k) {
      return static_cast<int>(indices.values[indices.offsets[f] + k]);
    };
    if (n > 3) ++polygons;
    for (std::size_t j = 1; j + 1 < n; ++j) {  // fan around corner 0
      mesh.triangles.push_back({corner(0), corner(j), corner(j + 1)});
      source.push_back(f);
      for (std::size_t c = 0; c < face_columns.size(); ++c)
        append_triangle_value(face_columns[c], f, n, j, j + 1, out[c]);
    }
  }
  mesh.face_extra = std::move(out);
  if (polygons > 0)
    mesh.notes.push_back(std::to_string(polygons) + " polygon(s) with more than 3 corners were " +
                         "fan-triangulated (" + std::to_string(mesh.triangles.size()) +
                         " triangles in all); their face properties were copied to each triangle");
  return source;
}

}  // namespace qd::io
