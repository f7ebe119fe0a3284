// Ours, not tinyobjloader: Debian 12's libtinyobjloader-dev (2.0.0~rc10), tried for issue 12,
// breaks our guarantees. It reads "v 0 0", "v 0 0 x" and "v nan 0 0" as zeros without a word,
// returns the face index -6 for "f 1 2 -9" silently, lets an index past the last vertex through
// with a warning only, drops two-corner faces without a line number, and its double build's
// pkg-config file lacks TINYOBJLOADER_USE_DOUBLE (coordinates then come back as garbage). Keeping
// "every bad line named with its number, nothing silently changed" on top of it would mean
// re-checking all it parsed, which is most of this file.
#include "io/obj_reader.h"

#include <cmath>
#include <map>
#include <string>

#include "common/error.h"
#include "io/text_scan.h"
#include "io/triangulate.h"

namespace qd::io {

namespace {

[[noreturn]] void fail(int line, const std::string& message) {
  throw common::Error("OBJ line " + std::to_string(line) + ": " + message);
}

// Everything gathered while scanning, before triangulation.
struct ObjScan {
  std::vector<std::array<double, 2>> uv;
  PlyProperty corners;    // vertex index lists, one per face
  PlyProperty corner_uv;  // u v per corner, one list per face
  bool all_faces_have_uv = true;
  std::vector<int> face_group;
  std::map<std::string, int> group_ids;
  int current_group = -1;   // -1 = no g/o line seen yet: the unnamed group
  std::size_t ignored = 0;  // l / p / unknown statements
};

// Resolves a 1-based (or negative, relative) OBJ index against `count` items seen so far.
std::size_t resolve_index(std::string_view token, std::size_t count, int line, const char* what) {
  long long i = 0;
  if (!parse_integer(token, i) || i == 0)
    fail(line, "'" + std::string(token) + "' is not a valid " + what + " index");
  const long long resolved = i > 0 ? i - 1 : static_cast<long long>(count) + i;
  if (resolved < 0 || resolved >= static_cast<long long>(count))
    fail(line, std::string(what) + " index " + std::to_string(i) + " is out of range (" +
                   std::to_string(count) + " defined so far)");
  return static_cast<std::size_t>(resolved);
}

std::array<double, 3> parse_vertex(const std::vector<std::string_view>& w, int line) {
  if (w.size() < 4) fail(line, "a vertex needs 3 coordinates");
  std::array<double, 3> p{};
  for (std::size_t k = 0; k < 3; ++k)
    if (!parse_number(w[k + 1], p[k]) || !std::isfinite(p[k]))
      fail(line, "vertex coordinate '" + std::string(w[k + 1]) + "' is not a finite number");
  return p;
}

void parse_face(const std::vector<std::string_view>& w, int line, std::size_t vertex_count,
                ObjScan& scan) {
  if (w.size() < 4) fail(line, "a face needs at least 3 corners");
  bool face_has_uv = true;
  std::vector<double> uv;
  for (std::size_t k = 1; k < w.size(); ++k) {
    const std::string_view corner = w[k];
    const std::size_t slash = corner.find('/');
    scan.corners.values.push_back(
        static_cast<double>(resolve_index(corner.substr(0, slash), vertex_count, line, "vertex")));
    const std::string_view rest =
        slash == std::string_view::npos ? std::string_view() : corner.substr(slash + 1);
    const std::string_view vt = rest.substr(0, rest.find('/'));
    if (vt.empty()) {
      face_has_uv = false;
      continue;
    }
    const std::array<double, 2>& t = scan.uv[resolve_index(vt, scan.uv.size(), line, "texture")];
    uv.insert(uv.end(), t.begin(), t.end());
  }
  scan.corners.offsets.push_back(scan.corners.values.size());
  scan.all_faces_have_uv = scan.all_faces_have_uv && face_has_uv;
  if (face_has_uv)
    for (double t : uv) scan.corner_uv.values.push_back(t);
  scan.corner_uv.offsets.push_back(scan.corner_uv.values.size());
  scan.face_group.push_back(scan.current_group);
}

void parse_group(std::string_view line, ObjScan& scan) {
  const std::vector<std::string_view> w = split_words(line);
  std::string name;
  for (std::size_t k = 1; k < w.size(); ++k) name += (k > 1 ? " " : "") + std::string(w[k]);
  const auto [it, added] = scan.group_ids.emplace(name, static_cast<int>(scan.group_ids.size()));
  scan.current_group = it->second;
}

// Patch id per group (-1 the unnamed one), numbered by first appearance on a face.
std::map<int, int> patch_id_of_group(const std::vector<int>& face_group) {
  std::map<int, int> id_of;
  for (int g : face_group) id_of.emplace(g, static_cast<int>(id_of.size()));
  return id_of;
}

}  // namespace

MeshDocument parse_obj(std::string_view bytes) {
  MeshDocument mesh;
  ObjScan scan;
  scan.corners.name = "vertex_indices";
  scan.corners.is_list = true;
  scan.corners.values = ScalarColumn(ScalarType::Int32);
  scan.corners.offsets.assign(1, 0);
  scan.corner_uv.values = ScalarColumn(ScalarType::Float64);
  scan.corner_uv.is_list = true;
  scan.corner_uv.offsets.assign(1, 0);
  std::size_t pos = 0;
  std::string_view line;
  int line_no = 0;
  while (next_line(bytes, pos, line)) {
    ++line_no;
    const std::vector<std::string_view> w = split_words(line.substr(0, line.find('#')));
    if (w.empty()) continue;
    if (w[0] == "v") {
      mesh.positions.push_back(parse_vertex(w, line_no));
    } else if (w[0] == "vt") {
      std::array<double, 2> t{};
      if (w.size() < 3 || !parse_number(w[1], t[0]) || !parse_number(w[2], t[1]))
        fail(line_no, "a texture coordinate needs 2 numbers");
      scan.uv.push_back(t);
    } else if (w[0] == "f") {
      parse_face(w, line_no, mesh.positions.size(), scan);
    } else if (w[0] == "g" || w[0] == "o") {
      parse_group(line.substr(0, line.find('#')), scan);
    } else if (w[0] == "l" || w[0] == "p") {
      ++scan.ignored;
    }
  }
  const std::size_t faces = scan.face_group.size();
  std::vector<PlyProperty> columns;
  if (scan.all_faces_have_uv)
    columns.push_back(std::move(scan.corner_uv));
  else if (!scan.uv.empty())
    mesh.notes.push_back("texture coordinates dropped: not every face has them");
  const std::vector<std::size_t> source =
      add_faces(scan.corners, faces, mesh.positions.size(), columns, mesh);
  if (!columns.empty()) {  // add_faces gave each triangle its three corners' u v
    const ScalarColumn& uv = mesh.face_extra[0].values;
    mesh.corner_uv.resize(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.corner_uv.size(); ++t)
      for (std::size_t k = 0; k < 6; ++k) mesh.corner_uv[t][k] = uv[6 * t + k];
    mesh.face_extra.clear();
  }
  if (!scan.group_ids.empty()) {
    const std::map<int, int> id_of = patch_id_of_group(scan.face_group);
    for (std::size_t s : source) mesh.patch.push_back(id_of.at(scan.face_group[s]));
    // Written as the face `patch` column, so the ids reach the next job (ply_mesh.h).
    mesh.face_extra.push_back(scalar_property(
        "patch", ScalarType::Int32, std::vector<double>(mesh.patch.begin(), mesh.patch.end())));
    for (const auto& [name, group] : scan.group_ids) {
      const auto id = id_of.find(group);
      if (id != id_of.end() && !name.empty()) mesh.patch_names[id->second] = name;
    }
    // Written to the output PLY as its comments, so the names reach the next job (ply_mesh.h).
    for (const auto& [id, name] : mesh.patch_names)
      mesh.comments.push_back("patch " + std::to_string(id) + " " + name);
  }
  if (scan.ignored > 0)
    mesh.notes.push_back(std::to_string(scan.ignored) + " OBJ line/point statement(s) ignored");
  return mesh;
}

}  // namespace qd::io
