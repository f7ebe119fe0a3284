// Face normal, face area and average edge length AE of a triangle mesh.
#include "mesh.h"

#include <algorithm>
#include <utility>

namespace qd {

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

double average_edge_length(const Positions& V, const Triangles& F, const std::vector<int>& faces) {
  const int count = faces.empty() ? static_cast<int>(F.rows()) : static_cast<int>(faces.size());
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    const int f = faces.empty() ? i : faces[i];
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k);
      const int b = F(f, (k + 1) % 3);
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  if (edges.empty()) return 0.0;
  double total = 0.0;
  for (const auto& e : edges) total += (V.row(e.first) - V.row(e.second)).norm();
  return total / static_cast<double>(edges.size());
}

}  // namespace qd
