// Face adjacency from the mesh's face edges sorted in linear time (mesh.h sorted_face_edges).
#include "segment/face_graph.h"

#include <cassert>

#include "segment/cone_proxy.h"

namespace qd::segment {

namespace {

// The side of face f on edge {a, b}, and whether f runs along it from a to b.
struct Side {
  int k;
  bool forward;
};

Side side_of(const Triangles& F, int f, int a, int b) {
  for (int k = 0; k < 3; ++k) {
    const int from = F(f, k), to = F(f, (k + 1) % 3);
    if (from == a && to == b) return {k, true};
    if (from == b && to == a) return {k, false};
  }
  return {-1, false};  // not reached: the edge is one of f's
}

}  // namespace

FaceGraph face_graph(const Positions& V, const Triangles& F, const std::vector<int>& region) {
  assert(region.empty() || region.size() == static_cast<size_t>(F.rows()));
  FaceGraph graph;
  const auto n = static_cast<size_t>(F.rows());
  graph.neighbour.assign(n, {-1, -1, -1});
  graph.side_length.resize(n);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      graph.side_length[f][k] = (V.row(F(f, (k + 1) % 3)) - V.row(F(f, k))).norm();

  const std::vector<FaceEdge> edges = sorted_face_edges(F, V.rows());
  for (size_t i = 0; i < edges.size();) {
    size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    const size_t faces = j - i;
    if (faces > 2) ++graph.nonmanifold_edges;
    if (faces == 2) {
      const int f = edges[i].face, h = edges[i + 1].face;
      const Side sf = side_of(F, f, edges[i].lo, edges[i].hi);
      const Side sh = side_of(F, h, edges[i].lo, edges[i].hi);
      if (sf.forward == sh.forward) {
        ++graph.misoriented_edges;
      } else if (!region.empty() && region[f] != region[h]) {
        ++graph.region_edges;
      } else {
        graph.neighbour[f][sf.k] = h;
        graph.neighbour[h][sh.k] = f;
      }
    }
    i = j;
  }
  return graph;
}

void remove_creases(FaceGraph& graph, const FaceGeometry& g, double crease) {
  for (size_t f = 0; f < graph.neighbour.size(); ++f)
    for (int& h : graph.neighbour[f])
      if (h >= 0 && angle_between(g.normal[f], g.normal[h]) > crease) {
        if (static_cast<size_t>(h) > f) graph.creases.push_back({static_cast<int>(f), h});
        h = -1;
      }
}

}  // namespace qd::segment
