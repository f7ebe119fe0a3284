#include "io/triangulate.h"

#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>

#include "common/error.h"
#include "common/format_text.h"

namespace qd::io {

namespace {

// Triangle (0, corner, corner + 1) of the fan of source face `face`.
struct FanTriangle {
  std::size_t face;
  std::size_t corner;
};

// Checks face f, whose vertex indices are corners[indices.offsets[f] ..].
void check_face(const PlyProperty& indices, const std::vector<double>& corners, std::size_t f,
                std::size_t vertex_count) {
  const std::size_t n = indices.list_size(f);
  if (n < 3)
    throw common::Error("face " + std::to_string(f) + " has " + std::to_string(n) +
                        " vertices; a face needs at least 3");
  for (std::size_t k = indices.offsets[f]; k < indices.offsets[f + 1]; ++k) {
    const double v = corners[k];
    if (v != std::floor(v))
      throw common::Error("face " + std::to_string(f) + " has vertex index " + std::to_string(v) +
                          ", which is not a whole number");
    if (v < 0 || v >= static_cast<double>(vertex_count))
      throw common::Error("face " + std::to_string(f) + " uses vertex index " +
                          common::format_text("%.0f", v) +  // any whole double, 2^63 and up too
                          ", out of range (the file has " + std::to_string(vertex_count) +
                          " vertices)");
  }
}

// Appends the entry of `column` (typed values `in`) for triangle t of an n-gon onto `out`.
template <typename T>
void append_triangle_entry(const PlyProperty& column, const std::vector<T>& in, FanTriangle t,
                           std::size_t n, std::vector<T>& out, std::vector<std::size_t>& offsets) {
  if (!column.is_list) {
    out.push_back(in[t.face]);
    return;
  }
  const std::size_t begin = column.offsets[t.face];
  const std::size_t length = column.list_size(t.face);
  if (n == 3 || length == 0 || length % n != 0) {
    out.insert(out.end(), in.begin() + static_cast<std::ptrdiff_t>(begin),
               in.begin() + static_cast<std::ptrdiff_t>(begin + length));
  } else {
    const std::size_t per_corner = length / n;
    for (std::size_t corner : {std::size_t{0}, t.corner, t.corner + 1})
      for (std::size_t k = 0; k < per_corner; ++k)
        out.push_back(in[begin + corner * per_corner + k]);
  }
  offsets.push_back(out.size());
}

// `column` with one entry per triangle of `fan`.
PlyProperty triangle_column(const PlyProperty& column, const PlyProperty& indices,
                            const std::vector<FanTriangle>& fan) {
  PlyProperty out;
  out.name = column.name;
  out.is_list = column.is_list;
  out.count_type = column.count_type;
  if (out.is_list) out.offsets.assign(1, 0);
  out.values = column.values.visit([&](const auto& in) {
    std::decay_t<decltype(in)> values;
    values.reserve(fan.size());
    for (const FanTriangle& t : fan)
      append_triangle_entry(column, in, t, indices.list_size(t.face), values, out.offsets);
    return ScalarColumn(std::move(values));
  });
  return out;
}

}  // namespace

std::vector<std::size_t> add_faces(const PlyProperty& indices, std::size_t face_count,
                                   std::size_t vertex_count,
                                   const std::vector<PlyProperty>& face_columns,
                                   MeshDocument& mesh) {
  const std::vector<double> corners = indices.values.to_doubles();
  std::vector<FanTriangle> fan;
  std::size_t polygons = 0;
  for (std::size_t f = 0; f < face_count; ++f) {
    check_face(indices, corners, f, vertex_count);
    const std::size_t n = indices.list_size(f);
    const auto corner = [&](std::size_t k) {
      return static_cast<int>(corners[indices.offsets[f] + k]);
    };
    if (n > 3) ++polygons;
    for (std::size_t j = 1; j + 1 < n; ++j) {  // fan around corner 0
      mesh.triangles.push_back({corner(0), corner(j), corner(j + 1)});
      fan.push_back({f, j});
    }
  }
  mesh.face_extra.clear();
  for (const PlyProperty& column : face_columns)
    mesh.face_extra.push_back(triangle_column(column, indices, fan));
  if (polygons > 0)
    mesh.notes.push_back(std::to_string(polygons) + " polygon(s) with more than 3 corners were " +
                         "fan-triangulated (" + std::to_string(mesh.triangles.size()) +
                         " triangles in all); their face properties were copied to each triangle");
  std::vector<std::size_t> source;
  source.reserve(fan.size());
  for (const FanTriangle& t : fan) source.push_back(t.face);
  return source;
}

}  // namespace qd::io
