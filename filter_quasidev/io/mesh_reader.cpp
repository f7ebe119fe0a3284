#include "io/mesh_reader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "common/error.h"
#include "io/obj_reader.h"
#include "io/off_reader.h"
#include "io/ply_mesh.h"

namespace qd::io {

namespace {

std::string lower_extension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool starts_with_word(const std::string& bytes, const std::string& word) {
  std::size_t i = 0;
  while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
  return bytes.compare(i, word.size(), word) == 0;
}

MeshDocument parse_by_content(const std::string& bytes, const std::string& path) {
  if (bytes.compare(0, 3, "ply") == 0) return parse_ply(bytes);
  const std::string ext = lower_extension(path);
  if (ext == "off" || starts_with_word(bytes, "OFF") || starts_with_word(bytes, "COFF") ||
      starts_with_word(bytes, "NOFF"))
    return parse_off(bytes);
  if (ext == "obj") return parse_obj(bytes);
  if (ext == "ply") return parse_ply(bytes);  // gives the PLY magic message
  throw common::Error("unknown mesh format (expected a .ply, .obj or .off file)");
}

}  // namespace

std::string read_file_bytes(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw common::Error("'" + path + "' is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw common::Error("cannot open '" + path + "': " + std::strerror(errno));
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

MeshDocument read_mesh(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  if (bytes.empty()) throw common::Error("'" + path + "' is empty");
  MeshDocument mesh;
  try {
    mesh = parse_by_content(bytes, path);
  } catch (const common::Error& e) {
    throw common::Error("'" + path + "': " + e.what());
  }
  if (mesh.triangles.empty())
    throw common::Error("'" + path + "' has no faces; quasidev needs a triangle mesh");
  return mesh;
}

}  // namespace qd::io
