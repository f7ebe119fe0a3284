#include "io/output_mesh.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"

namespace qd::meshio {

namespace {

// Area-weighted vertex normals of the positions V (unit length; zero where undefined).
std::vector<std::array<double, 3>> vertex_normals(const MeshFile& mesh, const Positions& V) {
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
std::array<int, 3> normal_columns(const PlyElement& vertex) {
  std::array<int, 3> columns = {-1, -1, -1};
  for (std::size_t i = 0; i < vertex.properties.size(); ++i) {
    const PlyProperty& p = vertex.properties[i];
    const int axis = p.name == "nx" ? 0 : p.name == "ny" ? 1 : p.name == "nz" ? 2 : -1;
    if (axis >= 0 && !p.is_list) columns[static_cast<std::size_t>(axis)] = static_cast<int>(i);
  }
  return columns;
}

// Removes the element's properties whose name `matches`.
template <typename Match>
void remove_columns(PlyElement& e, Match matches) {
  e.properties.erase(std::remove_if(e.properties.begin(), e.properties.end(),
                                    [&matches](const PlyProperty& p) { return matches(p.name); }),
                     e.properties.end());
}

void check_size(const PlyElement& e, std::size_t size) {
  if (size != e.count)
    throw Error("internal error: output fields do not have one value per " + e.name);
}

// A list property (uchar counts) of `type` with one list per row.
template <typename T, std::size_t N>
PlyProperty list_property(const std::string& name, ScalarType type,
                          const std::vector<std::array<T, N>>& rows) {
  PlyProperty p;
  p.name = name;
  p.is_list = true;
  p.count_type = ScalarType::UInt8;
  p.values = ScalarColumn(type);
  p.offsets.reserve(rows.size() + 1);
  p.offsets.push_back(0);
  for (const std::array<T, N>& row : rows) {
    for (T v : row) p.values.push_back(static_cast<double>(v));
    p.offsets.push_back(p.values.size());
  }
  return p;
}

}  // namespace

PlyFile output_ply(const MeshFile& mesh) {
  PlyFile ply;
  ply.format = PlyFormat::BinaryLittleEndian;
  ply.comments = mesh.comments;
  ply.obj_info = mesh.obj_info;
  PlyElement vertex;
  vertex.name = "vertex";
  vertex.count = mesh.positions.size();
  for (std::size_t k = 0; k < 3; ++k) {
    std::vector<double> c(vertex.count);
    for (std::size_t i = 0; i < vertex.count; ++i) c[i] = mesh.positions[i][k];
    vertex.properties.push_back(
        scalar_property(std::string(1, "xyz"[k]), mesh.position_types[k], c));
  }
  vertex.properties.insert(vertex.properties.end(), mesh.vertex_extra.begin(),
                           mesh.vertex_extra.end());
  PlyElement face;
  face.name = "face";
  face.count = mesh.triangles.size();
  face.properties.push_back(list_property("vertex_indices", ScalarType::Int32, mesh.triangles));
  if (!mesh.corner_uv.empty())
    face.properties.push_back(list_property("texcoord", ScalarType::Float32, mesh.corner_uv));
  face.properties.insert(face.properties.end(), mesh.face_extra.begin(), mesh.face_extra.end());
  ply.elements.push_back(std::move(vertex));
  ply.elements.push_back(std::move(face));
  ply.elements.insert(ply.elements.end(), mesh.other_elements.begin(), mesh.other_elements.end());
  return ply;
}

PlyElement& output_element(PlyFile& ply, const char* name) {
  for (PlyElement& e : ply.elements)
    if (e.name == name) return e;
  throw Error(std::string("internal error: the output has no element ") + name);
}

void set_positions(PlyFile& ply, const MeshFile& mesh, const Positions& V) {
  PlyElement& vertex = output_element(ply, "vertex");
  check_size(vertex, static_cast<std::size_t>(V.rows()));
  for (std::size_t k = 0; k < 3; ++k) {
    ScalarColumn& column = vertex.properties[k].values;
    column = ScalarColumn(ScalarType::Float64);
    column.reserve(vertex.count);
    for (std::size_t i = 0; i < vertex.count; ++i)
      column.push_back(V(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)));
  }
  const std::array<int, 3> normals = normal_columns(vertex);
  if (std::find(normals.begin(), normals.end(), -1) != normals.end()) return;
  const std::vector<std::array<double, 3>> n = vertex_normals(mesh, V);
  for (std::size_t k = 0; k < 3; ++k) {
    ScalarColumn& column = vertex.properties[static_cast<std::size_t>(normals[k])].values;
    column = ScalarColumn(column.type());
    column.reserve(vertex.count);
    for (std::size_t i = 0; i < vertex.count; ++i) column.push_back(n[i][k]);
  }
}

void set_quality(PlyElement& element, const std::vector<double>& quality) {
  check_size(element, quality.size());
  remove_columns(element, [](const std::string& name) { return name == "quality"; });
  element.properties.push_back(scalar_property("quality", ScalarType::Float64, quality));
}

void set_colors(PlyElement& element, const std::vector<std::array<unsigned char, 3>>& colors) {
  check_size(element, colors.size());
  remove_columns(element, [](const std::string& name) {
    return name == "red" || name == "green" || name == "blue" || name == "alpha";
  });
  const char* names[] = {"red", "green", "blue"};
  for (std::size_t k = 0; k < 3; ++k) {
    std::vector<double> c(colors.size());
    for (std::size_t i = 0; i < colors.size(); ++i) c[i] = colors[i][k];
    element.properties.push_back(scalar_property(names[k], ScalarType::UInt8, c));
  }
  element.properties.push_back(
      scalar_property("alpha", ScalarType::UInt8, std::vector<double>(colors.size(), 255)));
}

void set_texcoords(PlyElement& face, const WedgeUV& uv) {
  check_size(face, static_cast<std::size_t>(uv.rows()));
  remove_columns(face, [](const std::string& name) { return name == "texcoord"; });
  std::vector<std::array<double, 6>> rows(face.count);
  for (std::size_t f = 0; f < face.count; ++f)
    for (std::size_t k = 0; k < 6; ++k)
      rows[f][k] = uv(static_cast<Eigen::Index>(f), static_cast<Eigen::Index>(k));
  face.properties.push_back(list_property("texcoord", ScalarType::Float32, rows));
}

}  // namespace qd::meshio
