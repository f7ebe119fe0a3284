#include "io/output_mesh.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"
#include "io/ply_writer.h"

namespace qd::io {

namespace {

// Area-weighted vertex normals of the positions V (unit length; zero where undefined).
std::vector<std::array<double, 3>> vertex_normals(const MeshDocument& mesh,
                                                  const common::Positions& V) {
  const auto at = [&V](int v, Eigen::Index k) { return V(v, k); };
  std::vector<std::array<double, 3>> n(static_cast<std::size_t>(V.rows()), {0, 0, 0});
  for (const std::array<int, 3>& t : mesh.triangles) {
    const double u[3] = {at(t[1], 0) - at(t[0], 0), at(t[1], 1) - at(t[0], 1),
                         at(t[1], 2) - at(t[0], 2)};
    const double v[3] = {at(t[2], 0) - at(t[0], 0), at(t[2], 1) - at(t[0], 1),
                         at(t[2], 2) - at(t[0], 2)};
    const double cross[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                             u[0] * v[1] - u[1] * v[0]};  // twice the area times the normal
    for (int corner : t)
      for (std::size_t k = 0; k < 3; ++k) n[static_cast<std::size_t>(corner)][k] += cross[k];
  }
  for (auto& x : n) {
    const double length = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    if (length > 0)
      for (double& c : x) c /= length;
  }
  return n;
}

// Columns of the scalar properties nx, ny, nz, or -1 when one is missing.
std::array<int, 3> normal_columns(const std::vector<PlyProperty>& columns) {
  std::array<int, 3> found = {-1, -1, -1};
  for (std::size_t i = 0; i < columns.size(); ++i) {
    const PlyProperty& p = columns[i];
    const int axis = p.name == "nx" ? 0 : p.name == "ny" ? 1 : p.name == "nz" ? 2 : -1;
    if (axis >= 0 && !p.is_list) found[static_cast<std::size_t>(axis)] = static_cast<int>(i);
  }
  return found;
}

// Removes the columns whose name `matches`.
template <typename Match>
void remove_columns(std::vector<PlyProperty>& columns, Match matches) {
  columns.erase(std::remove_if(columns.begin(), columns.end(),
                               [&matches](const PlyProperty& p) { return matches(p.name); }),
                columns.end());
}

void check_size(const char* element, std::size_t rows, std::size_t size) {
  if (size != rows)
    throw common::Error(std::string("internal error: output fields do not have one value per ") +
                        element);
}

// The element's columns and its row count, checked against `size`.
std::vector<PlyProperty>& columns_of(MeshDocument& doc, Element element, std::size_t size) {
  if (element == Element::Vertex) {
    check_size("vertex", doc.positions.size(), size);
    return doc.vertex_extra;
  }
  check_size("face", doc.triangles.size(), size);
  return doc.face_extra;
}

// A list property (uchar counts) of `type` with one list per row.
template <typename T, std::size_t N>
PlyProperty list_property(const std::string& name, ScalarType type,
                          const std::vector<std::array<T, N>>& rows) {
  PlyProperty p;
  p.name = name;
  p.is_list = true;
  p.count_type = ScalarType::UInt8;
  std::vector<double> values;
  values.reserve(rows.size() * N);
  p.offsets.reserve(rows.size() + 1);
  p.offsets.push_back(0);
  for (const std::array<T, N>& row : rows) {
    values.insert(values.end(), row.begin(), row.end());
    p.offsets.push_back(values.size());
  }
  p.values = ScalarColumn(type, values);
  return p;
}

PlyTables tables_of(const MeshDocument& doc) {
  PlyTables ply;
  ply.comments = doc.comments;
  ply.obj_info = doc.obj_info;
  PlyElement vertex;
  vertex.name = "vertex";
  vertex.count = doc.positions.size();
  for (std::size_t k = 0; k < 3; ++k) {
    std::vector<double> c(vertex.count);
    for (std::size_t i = 0; i < vertex.count; ++i) c[i] = doc.positions[i][k];
    vertex.properties.push_back(
        scalar_property(std::string(1, "xyz"[k]), doc.position_types[k], c));
  }
  vertex.properties.insert(vertex.properties.end(), doc.vertex_extra.begin(),
                           doc.vertex_extra.end());
  PlyElement face;
  face.name = "face";
  face.count = doc.triangles.size();
  face.properties.push_back(list_property("vertex_indices", ScalarType::Int32, doc.triangles));
  if (!doc.corner_uv.empty())
    face.properties.push_back(list_property("texcoord", ScalarType::Float32, doc.corner_uv));
  face.properties.insert(face.properties.end(), doc.face_extra.begin(), doc.face_extra.end());
  ply.elements.push_back(std::move(vertex));
  ply.elements.push_back(std::move(face));
  ply.elements.insert(ply.elements.end(), doc.other_elements.begin(), doc.other_elements.end());
  return ply;
}

}  // namespace

void set_positions(MeshDocument& doc, const common::Positions& V) {
  check_size("vertex", doc.positions.size(), static_cast<std::size_t>(V.rows()));
  for (std::size_t i = 0; i < doc.positions.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k)
      doc.positions[i][k] = V(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k));
  doc.position_types = {ScalarType::Float64, ScalarType::Float64, ScalarType::Float64};
  const std::array<int, 3> normals = normal_columns(doc.vertex_extra);
  if (std::find(normals.begin(), normals.end(), -1) != normals.end()) return;
  const std::vector<std::array<double, 3>> n = vertex_normals(doc, V);
  for (std::size_t k = 0; k < 3; ++k) {
    ScalarColumn& column = doc.vertex_extra[static_cast<std::size_t>(normals[k])].values;
    std::vector<double> values(n.size());
    for (std::size_t i = 0; i < n.size(); ++i) values[i] = n[i][k];
    column = ScalarColumn(column.type(), values);
  }
}

void set_quality(MeshDocument& doc, Element element, const std::vector<double>& quality) {
  std::vector<PlyProperty>& columns = columns_of(doc, element, quality.size());
  remove_columns(columns, [](const std::string& name) { return name == "quality"; });
  columns.push_back(scalar_property("quality", ScalarType::Float64, quality));
}

void set_colors(MeshDocument& doc, Element element,
                const std::vector<std::array<unsigned char, 3>>& colors) {
  std::vector<PlyProperty>& columns = columns_of(doc, element, colors.size());
  remove_columns(columns, [](const std::string& name) {
    return name == "red" || name == "green" || name == "blue" || name == "alpha";
  });
  const char* names[] = {"red", "green", "blue"};
  for (std::size_t k = 0; k < 3; ++k) {
    std::vector<double> c(colors.size());
    for (std::size_t i = 0; i < colors.size(); ++i) c[i] = colors[i][k];
    columns.push_back(scalar_property(names[k], ScalarType::UInt8, c));
  }
  columns.push_back(
      scalar_property("alpha", ScalarType::UInt8, std::vector<double>(colors.size(), 255)));
}

void set_texcoords(MeshDocument& doc, const flatten::WedgeUV& uv) {
  std::vector<PlyProperty>& columns =
      columns_of(doc, Element::Face, static_cast<std::size_t>(uv.rows()));
  doc.corner_uv.clear();
  remove_columns(columns, [](const std::string& name) { return name == "texcoord"; });
  std::vector<std::array<double, 6>> rows(doc.triangles.size());
  for (std::size_t f = 0; f < rows.size(); ++f)
    for (std::size_t k = 0; k < 6; ++k)
      rows[f][k] = uv(static_cast<Eigen::Index>(f), static_cast<Eigen::Index>(k));
  columns.push_back(list_property("texcoord", ScalarType::Float32, rows));
}

std::string serialize_ply(const MeshDocument& doc, PlyFormat format) {
  return serialize_ply_tables(tables_of(doc), format);
}

}  // namespace qd::io
