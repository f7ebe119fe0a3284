#include "io/ply_mesh.h"

#include <climits>
#include <cmath>
#include <map>
#include <string>

#include "common/error.h"
#include "io/ply_reader.h"
#include "io/text_scan.h"
#include "io/triangulate.h"

namespace qd::io {

namespace {

[[noreturn]] void fail(const std::string& message) { throw common::Error("PLY: " + message); }

// Removes and returns the scalar property `name` of `e`; fails if it is missing or a list.
PlyProperty take_scalar(PlyElement& e, const std::string& name) {
  const int i = e.find(name);
  if (i < 0) fail("the '" + e.name + "' element has no '" + name + "' property");
  PlyProperty p = std::move(e.properties[static_cast<std::size_t>(i)]);
  e.properties.erase(e.properties.begin() + i);
  if (p.is_list) fail("the '" + e.name + "' property '" + name + "' is a list, expected a scalar");
  return p;
}

void read_vertices(PlyElement& vertex, MeshDocument& mesh) {
  const PlyProperty x = take_scalar(vertex, "x");
  const PlyProperty y = take_scalar(vertex, "y");
  const PlyProperty z = take_scalar(vertex, "z");
  mesh.positions.resize(vertex.count);
  mesh.position_types = {x.type(), y.type(), z.type()};
  const std::vector<double> xs = x.values.to_doubles(), ys = y.values.to_doubles(),
                            zs = z.values.to_doubles();
  for (std::size_t i = 0; i < vertex.count; ++i) {
    mesh.positions[i] = {xs[i], ys[i], zs[i]};
    for (double c : mesh.positions[i])
      if (!std::isfinite(c))
        fail("vertex " + std::to_string(i) + " has a non-finite coordinate (" + std::to_string(c) +
             "); fix or remove it");
  }
  const int flags = vertex.find("flags");
  if (flags >= 0 && !vertex.properties[static_cast<std::size_t>(flags)].is_list) {
    const std::vector<double> values =
        vertex.properties[static_cast<std::size_t>(flags)].values.to_doubles();
    std::vector<char> selected(vertex.count, 0);
    bool any = false;
    for (std::size_t i = 0; i < vertex.count; ++i) {
      selected[i] = has_selected_flag(values[i]);
      any = any || selected[i];
    }
    if (any) mesh.constrained = std::move(selected);
  }
  mesh.vertex_extra = std::move(vertex.properties);
}

// Patch id per source face from `quality` (rounded) or `patch`; empty if neither exists.
std::vector<int> face_patch_ids(const PlyElement& face) {
  int column = face.find("quality");
  if (column < 0) column = face.find("patch");
  if (column < 0) return {};
  const PlyProperty& p = face.properties[static_cast<std::size_t>(column)];
  if (p.is_list) fail("the face property '" + p.name + "' is a list; expected one patch id");
  const std::vector<double> values = p.values.to_doubles();
  std::vector<int> ids(face.count);
  for (std::size_t f = 0; f < face.count; ++f) {
    const double v = std::round(values[f]);
    if (!std::isfinite(v) || std::fabs(v) > 1e9)
      fail("face " + std::to_string(f) + " has " + p.name + " " + std::to_string(values[f]) +
           ", not usable as a patch id");
    ids[f] = static_cast<int>(v);
  }
  return ids;
}

void read_faces(PlyElement& face, MeshDocument& mesh) {
  const std::string name = face.find("vertex_indices") >= 0 ? "vertex_indices" : "vertex_index";
  const int i = face.find(name);
  if (i < 0) fail("the 'face' element has no 'vertex_indices' list");
  PlyProperty indices = std::move(face.properties[static_cast<std::size_t>(i)]);
  face.properties.erase(face.properties.begin() + i);
  if (!indices.is_list) fail("the face property '" + name + "' is not a list");
  const std::vector<int> ids = face_patch_ids(face);
  try {
    const std::vector<std::size_t> source =
        add_faces(indices, face.count, mesh.positions.size(), face.properties, mesh);
    if (!ids.empty())
      for (std::size_t s : source) mesh.patch.push_back(ids[s]);
  } catch (const common::Error& e) {
    fail(e.what());
  }
}

// Panel names from the comments "patch <id> <name…>"; other comments name nothing.
std::map<int, std::string> patch_names(const std::vector<std::string>& comments) {
  std::map<int, std::string> names;
  for (const std::string& comment : comments) {
    const std::vector<std::string_view> w = split_words(comment);
    long long id = 0;
    if (w.size() < 3 || w[0] != "patch" || !parse_integer(w[1], id) || id < INT_MIN || id > INT_MAX)
      continue;
    const std::size_t from = static_cast<std::size_t>(w[2].data() - comment.data());
    const std::size_t to =
        static_cast<std::size_t>(w.back().data() + w.back().size() - comment.data());
    names[static_cast<int>(id)] = comment.substr(from, to - from);
  }
  return names;
}

}  // namespace

bool has_selected_flag(double flags) {
  if (!(std::fabs(flags) < 0x1p58)) return false;
  return (static_cast<long long>(flags) & kSelectedFlag) != 0;
}

MeshDocument parse_ply(std::string_view bytes) {
  PlyTables ply = parse_ply_tables(bytes);
  MeshDocument mesh;
  mesh.patch_names = patch_names(ply.comments);
  mesh.comments = std::move(ply.comments);
  mesh.obj_info = std::move(ply.obj_info);
  PlyElement* vertex = nullptr;
  PlyElement* face = nullptr;
  for (PlyElement& e : ply.elements) {
    if (e.name == "vertex")
      vertex = &e;
    else if (e.name == "face")
      face = &e;
  }
  if (!vertex) fail("the file has no 'vertex' element");
  if (!face) fail("the file has no 'face' element (quasidev needs a triangle mesh)");
  read_vertices(*vertex, mesh);
  read_faces(*face, mesh);
  for (PlyElement& e : ply.elements)
    if (&e != vertex && &e != face) mesh.other_elements.push_back(std::move(e));
  return mesh;
}

}  // namespace qd::io
