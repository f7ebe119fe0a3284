// Face normal, face area and average edge length AE of a triangle mesh.
#include "common/mesh.h"

#include <algorithm>
#include <cstddef>

namespace qd::common {

namespace {

// (v2 − v1) × (v3 − v1): twice the area times the unit normal.
Vec3 doubled_area_vector(const Positions& V, const Triangles& F, int f) {
  const Vec3 a = V.row(F(f, 0)).transpose();
  const Vec3 b = V.row(F(f, 1)).transpose();
  const Vec3 c = V.row(F(f, 2)).transpose();
  return (b - a).cross(c - a);
}

}  // namespace

Vec3 face_normal(const Positions& V, const Triangles& F, int f) {
  const Vec3 n = doubled_area_vector(V, F, f);
  const double length = n.norm();
  return length > 0 ? Vec3(n / length) : Vec3::Zero();
}

double face_area(const Positions& V, const Triangles& F, int f) {
  return 0.5 * doubled_area_vector(V, F, f).norm();
}

std::vector<FaceEdge> sorted_face_edges(const Triangles& F, Eigen::Index vertex_count,
                                        const std::vector<int>& faces) {
  const size_t count = faces.empty() ? static_cast<size_t>(F.rows()) : faces.size();
  auto for_each_edge = [&](auto&& visit) {
    for (size_t i = 0; i < count; ++i) {
      const int f = faces.empty() ? static_cast<int>(i) : faces[i];
      for (int k = 0; k < 3; ++k) {
        const int a = F(f, k), b = F(f, (k + 1) % 3);
        visit(FaceEdge{std::min(a, b), std::max(a, b), f});
      }
    }
  };
  std::vector<size_t> start(static_cast<size_t>(vertex_count) + 1, 0);
  for_each_edge([&](const FaceEdge& e) { ++start[static_cast<size_t>(e.lo) + 1]; });
  for (size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<FaceEdge> edges(3 * count);
  std::vector<size_t> next(start.begin(), start.end() - 1);
  for_each_edge([&](const FaceEdge& e) { edges[next[static_cast<size_t>(e.lo)]++] = e; });
  const auto by_hi_face = [](const FaceEdge& x, const FaceEdge& y) {
    return x.hi != y.hi ? x.hi < y.hi : x.face < y.face;
  };
  for (size_t v = 0; v + 1 < start.size(); ++v)
    std::sort(edges.begin() + static_cast<std::ptrdiff_t>(start[v]),
              edges.begin() + static_cast<std::ptrdiff_t>(start[v + 1]), by_hi_face);
  return edges;
}

double average_edge_length(const Positions& V, const Triangles& F, const std::vector<int>& faces) {
  double total = 0.0;
  size_t unique = 0;
  const std::vector<FaceEdge> edges = sorted_face_edges(F, V.rows(), faces);
  for (size_t i = 0; i < edges.size(); ++i) {
    if (i > 0 && edges[i].lo == edges[i - 1].lo && edges[i].hi == edges[i - 1].hi) continue;
    total += (V.row(edges[i].lo) - V.row(edges[i].hi)).norm();
    ++unique;
  }
  return unique > 0 ? total / static_cast<double>(unique) : 0.0;
}

int corner_of(const Triangles& F, int f, int v) {
  for (int k = 0; k < 3; ++k)
    if (F(f, k) == v) return 3 * f + k;
  return -1;
}

}  // namespace qd::common
