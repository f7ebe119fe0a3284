#include "io/constraint_file.h"

#include "common/error.h"
#include "io/mesh_reader.h"
#include "io/text_scan.h"

namespace qd::io {

std::vector<std::size_t> read_constraint_file(const std::string& path, std::size_t vertex_count) {
  const std::string bytes = read_file_bytes(path);
  std::vector<std::size_t> indices;
  std::size_t pos = 0;
  std::string_view line;
  int line_no = 0;
  while (next_line(bytes, pos, line)) {
    ++line_no;
    const std::string at = "constraints '" + path + "' line " + std::to_string(line_no) + ": ";
    const std::vector<std::string_view> w = split_words(line.substr(0, line.find('#')));
    if (w.empty()) continue;
    if (w.size() > 1) throw common::Error(at + "expected one vertex index per line");
    long long i = 0;
    if (!parse_integer(w[0], i))
      throw common::Error(at + "'" + std::string(w[0]) + "' is not a vertex index");
    if (i < 0 || i >= static_cast<long long>(vertex_count))
      throw common::Error(at + "vertex index " + std::to_string(i) +
                          " is out of range (the mesh has " + std::to_string(vertex_count) +
                          " vertices, indices start at 0)");
    indices.push_back(static_cast<std::size_t>(i));
  }
  return indices;
}

}  // namespace qd::io
