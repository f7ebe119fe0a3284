#include "flatten/piece_measures.h"

#include <algorithm>

#include "flatten/boundary_crossings.h"
#include "flatten/face_distortion.h"

namespace qd::flatten {

namespace {

// Twice the signed area of face f in the plane.
double doubled_flat_area(const Triangles& F, const Eigen::MatrixX2d& uv, int f) {
  const Eigen::RowVector2d a = uv.row(F(f, 1)) - uv.row(F(f, 0)),
                           b = uv.row(F(f, 2)) - uv.row(F(f, 0));
  return a.x() * b.y() - a.y() * b.x();
}

// The face along the boundary edge from a to b.
int face_of_boundary_edge(const EdgeTable& edges, int a, int b) {
  for (int i = edges.first[a]; i < edges.first[a + 1]; ++i)
    if (edges.other_end(edges.at[i], a) == b) return edges.faces[edges.at[i]][0];
  return -1;
}

}  // namespace

PieceMeasures measure_piece(const Positions& V, const Triangles& F, const FlatTriangles& g,
                            const EdgeTable& edges, const std::vector<std::vector<int>>& loops,
                            const Eigen::MatrixX2d& uv) {
  PieceMeasures m;
  m.stretch.resize(static_cast<size_t>(F.rows()));
  double area = 0, flat_area = 0, weighted = 0;
  for (int f = 0; f < F.rows(); ++f) {
    const Stretch s = stretch(face_jacobian(g, F, uv, f));
    m.stretch[f] = signed_stretch(s);
    m.max_distortion = std::max(m.max_distortion, length_distortion(s));
    weighted += g.area(f) * length_distortion(s);
    area += g.area(f);
    flat_area += 0.5 * doubled_flat_area(F, uv, f);
    m.flipped += s.flipped;
  }
  m.max_distortion *= 100;
  m.mean_distortion = area > 0 ? 100 * weighted / area : 0;
  m.area_change = area > 0 ? 100 * (flat_area - area) / area : 0;

  std::vector<std::array<int, 2>> segments;
  double length = 0, flat_length = 0;
  for (const std::vector<int>& loop : loops)
    for (size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      segments.push_back({a, b});
      length += (V.row(b) - V.row(a)).norm();
      flat_length += (uv.row(b) - uv.row(a)).norm();
    }
  m.boundary_change = length > 0 ? 100 * (flat_length - length) / length : 0;
  const std::vector<char> crossing = crossing_segments(uv, segments);
  std::vector<int> faces;
  for (size_t s = 0; s < segments.size(); ++s)
    if (crossing[s]) faces.push_back(face_of_boundary_edge(edges, segments[s][0], segments[s][1]));
  std::sort(faces.begin(), faces.end());
  m.overlapping = static_cast<int>(std::unique(faces.begin(), faces.end()) - faces.begin());
  return m;
}

}  // namespace qd::flatten
