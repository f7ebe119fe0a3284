#include "flatten/cut_to_disk.h"

#include <algorithm>

#include "common/disjoint_sets.h"
#include "common/error.h"
#include "common/format_text.h"
#include "flatten/boundary_loops.h"
#include "flatten/common_names.h"
#include "flatten/shortest_paths.h"
#include "flatten/split_corners.h"

namespace qd::flatten {

namespace {

struct Shape {
  EdgeTable edges;
  std::vector<std::vector<int>> loops;
  int genus = 0;
};

Shape shape_of(const Piece& p) {
  Shape s;
  const int n = static_cast<int>(p.V.rows());
  s.edges = edge_table(p.F, n);
  s.loops = boundary_loops(p.F, s.edges);
  const int chi = euler_characteristic(p.F, s.edges, n);
  s.genus = (2 - chi - static_cast<int>(s.loops.size())) / 2;  // χ = 2 − 2g − b
  return s;
}

bool is_disk(const Shape& s) { return s.loops.size() == 1 && s.genus == 0; }

// Marks the edges of `path` as cut and adds them to the tally.
void cut_along(const Piece& p, const EdgeTable& edges, const std::vector<int>& path,
               std::vector<char>& cut, DiskCut& tally) {
  for (const int e : path) {
    if (cut[e]) continue;
    cut[e] = 1;
    ++tally.edges;
    tally.length += edge_length(p.V, edges, e);
  }
}

void open_up(Piece& p, const EdgeTable& edges, const std::vector<char>& cut) {
  const SplitMesh split = split_corners(p.F, edges, cut);
  renumber_vertices(p, split.F, split.origin);
}

double loop_length(const Positions& V, const std::vector<int>& loop) {
  double length = 0;
  for (size_t i = 0; i < loop.size(); ++i)
    length += (V.row(loop[i]) - V.row(loop[(i + 1) % loop.size()])).norm();
  return length;
}

// Joins every boundary loop to the longest one: b − 1 shortest paths, nearest loop first.
void join_loops(Piece& p, const Shape& s, DiskCut& tally) {
  const size_t b = s.loops.size();
  std::vector<double> length(b);
  for (size_t k = 0; k < b; ++k) length[k] = loop_length(p.V, s.loops[k]);
  const size_t longest =
      static_cast<size_t>(std::max_element(length.begin(), length.end()) - length.begin());
  std::vector<int> loop_of(static_cast<size_t>(p.V.rows()), -1);
  for (size_t k = 0; k < b; ++k)
    for (const int v : s.loops[k]) loop_of[v] = static_cast<int>(k);
  std::vector<char> joined(b, 0), cut(static_cast<size_t>(s.edges.count()), 0);
  joined[longest] = 1;
  std::vector<int> sources = s.loops[longest];
  for (size_t j = 1; j < b; ++j) {
    const ShortestPaths paths = shortest_paths(p.V, s.edges, sources);
    int nearest = -1;  // vertex of an unjoined loop nearest to the joined ones (lowest index)
    for (int v = 0; v < p.V.rows(); ++v)
      if (loop_of[v] >= 0 && !joined[loop_of[v]] &&
          (nearest < 0 || paths.distance[v] < paths.distance[nearest]))
        nearest = v;
    const std::vector<int> path = path_to_source(paths, s.edges, nearest);
    cut_along(p, s.edges, path, cut, tally);
    ++tally.joining_paths;
    joined[loop_of[nearest]] = 1;
    sources.insert(sources.end(), s.loops[loop_of[nearest]].begin(),
                   s.loops[loop_of[nearest]].end());
    for (const int e : path)
      sources.insert(sources.end(), s.edges.ends[e].begin(), s.edges.ends[e].end());
  }
  open_up(p, s.edges, cut);
}

// Cuts the greedy system of loops through `sources` (see the header), and for a closed
// genus-0 piece the slit from the source to the farthest vertex.
void cut_loops(Piece& p, const Shape& s, const std::vector<int>& sources, DiskCut& tally) {
  const EdgeTable& edges = s.edges;
  const ShortestPaths paths = shortest_paths(p.V, edges, sources);
  std::vector<char> in_tree(static_cast<size_t>(edges.count()), 0);
  for (const int e : paths.parent_edge)
    if (e >= 0) in_tree[e] = 1;
  std::vector<int> dual;  // edges the dual spanning tree may cross, longest loop first
  std::vector<double> loop(static_cast<size_t>(edges.count()), 0);
  for (int e = 0; e < edges.count(); ++e) {
    if (!edges.interior(e) || in_tree[e]) continue;
    dual.push_back(e);
    loop[e] = paths.distance[edges.ends[e][0]] + paths.distance[edges.ends[e][1]] +
              edge_length(p.V, edges, e);
  }
  std::stable_sort(dual.begin(), dual.end(), [&](int a, int b) { return loop[a] > loop[b]; });
  DisjointSets faces(static_cast<size_t>(p.F.rows()));
  std::vector<char> cut(static_cast<size_t>(edges.count()), 0);
  for (const int e : dual) {
    if (faces.join(edges.faces[e][0], edges.faces[e][1])) continue;
    cut_along(p, edges, {e}, cut, tally);
    for (const int v : edges.ends[e])
      cut_along(p, edges, path_to_source(paths, edges, v), cut, tally);
    ++tally.handle_loops;
  }
  if (s.loops.empty() && s.genus == 0) {
    const auto farthest = std::max_element(paths.distance.begin(), paths.distance.end());
    cut_along(p, edges,
              path_to_source(paths, edges, static_cast<int>(farthest - paths.distance.begin())),
              cut, tally);
    tally.slit = true;
  }
  open_up(p, edges, cut);
}

std::string note_of(const DiskCut& c, int loops, int genus) {
  std::string out = "cut to a disk along ";
  if (c.joining_paths > 0)
    out += format_text("%d %s joining its %d boundary loops", c.joining_paths,
                       c.joining_paths == 1 ? "shortest path" : "shortest paths", loops);
  if (c.joining_paths > 0 && (c.handle_loops > 0 || c.slit)) out += " and ";
  if (c.handle_loops > 0)
    out += format_text("%d loops around its %d %s", c.handle_loops, genus,
                       genus == 1 ? "handle" : "handles");
  if (c.slit) out += "a slit (the patch is closed)";
  return out + format_text(": %d edges, length %.4g", c.edges, c.length);
}

}  // namespace

DiskCut cut_to_disk(Piece& piece) {
  DiskCut tally;
  Shape s = shape_of(piece);
  if (is_disk(s)) return tally;
  const int loops = static_cast<int>(s.loops.size()), genus = s.genus;
  if (loops >= 2) {
    join_loops(piece, s, tally);
    s = shape_of(piece);
  }
  if (s.loops.empty()) {  // closed: loops through, or a slit from, the farthest vertex
    const std::vector<int> from_first = {0};
    const std::vector<double> d = shortest_paths(piece.V, s.edges, from_first).distance;
    cut_loops(piece, s, {static_cast<int>(std::max_element(d.begin(), d.end()) - d.begin())},
              tally);
  } else if (s.genus > 0) {
    cut_loops(piece, s, s.loops[0], tally);
  }
  if (!is_disk(shape_of(piece)))
    throw Error("patch " + std::to_string(piece.patch) +
                " could not be cut into a disk (non-manifold edges inside it?): repair the mesh "
                "(MeshLab: Filters > Cleaning and Repairing) or split the patch.");
  tally.note = note_of(tally, loops, genus);
  return tally;
}

}  // namespace qd::flatten
