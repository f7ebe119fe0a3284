#include "io/off_reader.h"

#include <cmath>
#include <string>

#include "common/error.h"
#include "io/text_scan.h"
#include "io/triangulate.h"

namespace qd::io {

namespace {

[[noreturn]] void fail(int line, const std::string& message) {
  throw common::Error("OFF line " + std::to_string(line) + ": " + message);
}

// Non-empty lines with comments removed, each with its 1-based line number.
struct OffLines {
  std::vector<std::vector<std::string_view>> words;
  std::vector<int> number;
};

OffLines significant_lines(std::string_view bytes) {
  OffLines lines;
  std::size_t pos = 0;
  std::string_view line;
  int line_no = 0;
  while (next_line(bytes, pos, line)) {
    ++line_no;
    std::vector<std::string_view> w = split_words(line.substr(0, line.find('#')));
    if (w.empty()) continue;
    lines.words.push_back(std::move(w));
    lines.number.push_back(line_no);
  }
  return lines;
}

std::size_t parse_count(std::string_view token, int line, const char* what) {
  long long n = 0;
  if (!parse_integer(token, n) || n < 0)
    fail(line,
         std::string(what) + " count '" + std::string(token) + "' is not a non-negative integer");
  return static_cast<std::size_t>(n);
}

}  // namespace

MeshDocument parse_off(std::string_view bytes) {
  const OffLines lines = significant_lines(bytes);
  if (lines.words.empty()) throw common::Error("OFF: the file is empty");
  std::vector<std::string_view> header = lines.words[0];
  const std::string keyword(header[0]);
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0 ||
      keyword.find_first_not_of("CNST") != keyword.size() - 3)
    fail(lines.number[0], "the file does not start with 'OFF' (not an OFF file)");
  std::size_t next = 1;
  header.erase(header.begin());
  if (header.empty()) {  // counts on their own line
    if (next >= lines.words.size()) throw common::Error("OFF: the counts line is missing");
    header = lines.words[next++];
  }
  const int count_line = lines.number[next - 1];
  if (header.size() < 2) fail(count_line, "expected 'VERTICES FACES [EDGES]'");
  const std::size_t nv = parse_count(header[0], count_line, "vertex");
  const std::size_t nf = parse_count(header[1], count_line, "face");
  const std::size_t available = lines.words.size() - next;
  if (nv > available || nf > available - nv)
    throw common::Error("OFF: the header declares " + std::to_string(nv) + " vertices and " +
                        std::to_string(nf) + " faces, but only " + std::to_string(available) +
                        " data lines follow (wrong counts or truncated file)");
  MeshDocument mesh;
  mesh.positions.resize(nv);
  for (std::size_t i = 0; i < nv; ++i, ++next) {
    const std::vector<std::string_view>& w = lines.words[next];
    if (w.size() < 3) fail(lines.number[next], "a vertex needs 3 coordinates");
    for (std::size_t k = 0; k < 3; ++k)
      if (!parse_number(w[k], mesh.positions[i][k]) || !std::isfinite(mesh.positions[i][k]))
        fail(lines.number[next],
             "vertex coordinate '" + std::string(w[k]) + "' is not a finite number");
  }
  PlyProperty corners;  // double holds any index read, so add_faces can name one out of range
  corners.values = ScalarColumn(ScalarType::Float64);
  corners.is_list = true;
  corners.offsets.assign(1, 0);
  for (std::size_t f = 0; f < nf; ++f, ++next) {
    const std::vector<std::string_view>& w = lines.words[next];
    const std::size_t n = parse_count(w[0], lines.number[next], "face corner");
    if (w.size() < n + 1)
      fail(lines.number[next], "the face lists " + std::to_string(w.size() - 1) +
                                   " indices but says it has " + std::to_string(n));
    for (std::size_t k = 1; k <= n; ++k) {
      long long v = 0;
      if (!parse_integer(w[k], v))
        fail(lines.number[next], "'" + std::string(w[k]) + "' is not a vertex index");
      corners.values.push_back(static_cast<double>(v));
    }
    corners.offsets.push_back(corners.values.size());
  }
  try {
    add_faces(corners, nf, nv, {}, mesh);
  } catch (const common::Error& e) {
    throw common::Error(std::string("OFF: ") + e.what());
  }
  return mesh;
}

}  // namespace qd::io
