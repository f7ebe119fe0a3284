#include "io/output_mesh.h"

#include <cmath>
#include <string>

#include "common/error.h"

namespace qd::meshio {

namespace {

bool is_color(const std::string& name) {
  return name == "red" || name == "green" || name == "blue" || name == "alpha";
}

// True when the vertex has scalar nx, ny and nz (stale after the move: they are recomputed).
bool has_normals(const std::vector<PlyProperty>& vertex_extra) {
  int found = 0;
  for (const PlyProperty& p : vertex_extra)
    if (!p.is_list && (p.name == "nx" || p.name == "ny" || p.name == "nz")) ++found;
  return found == 3;
}

// Area-weighted vertex normals of the new positions (unit length; zero where undefined).
std::vector<std::array<double, 3>> vertex_normals(const MeshFile& mesh,
                                                  const std::vector<std::array<double, 3>>& V) {
  std::vector<std::array<double, 3>> n(V.size(), {0, 0, 0});
  for (const std::array<int, 3>& t : mesh.triangles) {
    const auto& a = V[static_cast<std::size_t>(t[0])];
    const auto& b = V[static_cast<std::size_t>(t[1])];
    const auto& c = V[static_cast<std::size_t>(t[2])];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
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

// Appends `red green blue alpha` (uchar, alpha 255) holding `colors`.
void add_colors(PlyElement& e, const std::vector<std::array<unsigned char, 3>>& colors) {
  const char* names[] = {"red", "green", "blue"};
  for (std::size_t k = 0; k < 3; ++k) {
    std::vector<double> c(colors.size());
    for (std::size_t i = 0; i < colors.size(); ++i) c[i] = colors[i][k];
    e.properties.push_back(scalar_property(names[k], ScalarType::UInt8, c));
  }
  e.properties.push_back(
      scalar_property("alpha", ScalarType::UInt8, std::vector<double>(colors.size(), 255)));
}

// A list property (uchar counts) of `type` with one list per row.
template <typename T, std::size_t N>
PlyProperty list_property(const std::string& name, ScalarType type,
                          const std::vector<std::array<T, N>>& rows) {
  PlyProperty p;
  p.name = name;
  p.is_list = true;
  p.count_type = ScalarType::UInt8;
  p.type = type;
  p.offsets.reserve(rows.size() + 1);
  p.offsets.push_back(0);
  for (const std::array<T, N>& row : rows) {
    p.values.insert(p.values.end(), row.begin(), row.end());
    p.offsets.push_back(p.values.size());
  }
  return p;
}

// True when `values` is empty (not written) or has one entry per element.
template <typename T>
bool fits(const std::vector<T>& values, std::size_t count) {
  return values.empty() || values.size() == count;
}

// The input's extra properties, without those the fields replace: `quality` when quality is
// written, the colour channels when colours are, `texcoord` when texture coordinates are.
std::vector<PlyProperty> kept(const std::vector<PlyProperty>& extra, bool quality, bool colors,
                              bool texcoords) {
  std::vector<PlyProperty> out;
  for (const PlyProperty& p : extra)
    if (!(quality && p.name == "quality") && !(colors && is_color(p.name)) &&
        !(texcoords && p.name == "texcoord"))
      out.push_back(p);
  return out;
}

PlyElement vertex_element(const MeshFile& mesh, const OutputFields& fields) {
  const std::size_t nv = mesh.positions.size();
  const bool moved = !fields.positions.empty();
  if (!fits(fields.positions, nv) || !fits(fields.quality, nv) || !fits(fields.colors, nv))
    throw Error("internal error: output fields do not have one value per vertex");
  PlyElement e;
  e.name = "vertex";
  e.count = nv;
  const std::vector<std::array<double, 3>>& positions = moved ? fields.positions : mesh.positions;
  for (std::size_t k = 0; k < 3; ++k) {
    std::vector<double> c(nv);
    for (std::size_t i = 0; i < nv; ++i) c[i] = positions[i][k];
    e.properties.push_back(scalar_property(
        std::string(1, "xyz"[k]), moved ? ScalarType::Float64 : mesh.position_types[k], c));
  }
  const bool normals = moved && has_normals(mesh.vertex_extra);
  std::vector<std::array<double, 3>> n;
  for (const PlyProperty& p :
       kept(mesh.vertex_extra, !fields.quality.empty(), !fields.colors.empty(), false)) {
    e.properties.push_back(p);
    const int axis = p.name == "nx" ? 0 : p.name == "ny" ? 1 : p.name == "nz" ? 2 : -1;
    if (axis < 0 || p.is_list || !normals) continue;
    if (n.empty()) n = vertex_normals(mesh, fields.positions);
    for (std::size_t i = 0; i < nv; ++i)
      e.properties.back().values[i] = n[i][static_cast<std::size_t>(axis)];
  }
  if (!fields.quality.empty())
    e.properties.push_back(scalar_property("quality", ScalarType::Float64, fields.quality));
  if (!fields.colors.empty()) add_colors(e, fields.colors);
  return e;
}

// Index of the face property called `name` among the input's, or -1.
int mesh_face_column(const MeshFile& mesh, const std::string& name) {
  for (std::size_t i = 0; i < mesh.face_extra.size(); ++i)
    if (mesh.face_extra[i].name == name) return static_cast<int>(i);
  return -1;
}

PlyElement face_element(const MeshFile& mesh, const OutputFields& fields) {
  const std::size_t nf = mesh.triangles.size();
  if (!fits(fields.texcoords, nf) || !fits(fields.face_quality, nf) ||
      !fits(fields.face_colors, nf))
    throw Error("internal error: output fields do not have one value per face");
  PlyElement e;
  e.name = "face";
  e.count = nf;
  e.properties.push_back(list_property("vertex_indices", ScalarType::Int32, mesh.triangles));
  const std::vector<PlyProperty> extra =
      kept(mesh.face_extra, !fields.face_quality.empty(), !fields.face_colors.empty(),
           !fields.texcoords.empty());
  e.properties.insert(e.properties.end(), extra.begin(), extra.end());
  // Patch ids that no face property holds (OBJ groups) are written as `patch`, so they survive.
  if (!mesh.patch.empty() && mesh_face_column(mesh, "patch") < 0 &&
      mesh_face_column(mesh, "quality") < 0)
    e.properties.push_back(scalar_property(
        "patch", ScalarType::Int32, std::vector<double>(mesh.patch.begin(), mesh.patch.end())));
  if (!fields.texcoords.empty())
    e.properties.push_back(list_property("texcoord", ScalarType::Float32, fields.texcoords));
  if (!fields.face_quality.empty())
    e.properties.push_back(scalar_property("quality", ScalarType::Float64, fields.face_quality));
  if (!fields.face_colors.empty()) add_colors(e, fields.face_colors);
  return e;
}

}  // namespace

PlyFile output_ply(const MeshFile& mesh, const OutputFields& fields) {
  PlyFile ply;
  ply.format = PlyFormat::BinaryLittleEndian;
  ply.comments = mesh.comments;
  ply.obj_info = mesh.obj_info;
  ply.elements.push_back(vertex_element(mesh, fields));
  ply.elements.push_back(face_element(mesh, fields));
  ply.elements.insert(ply.elements.end(), mesh.other_elements.begin(), mesh.other_elements.end());
  return ply;
}

}  // namespace qd::meshio
