#include "approximate/angle_defect.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "approximate/common_names.h"
#include "common/metrics.h"

namespace qd::approximate {
namespace {

// Position of local vertex u in the star of row r (appended when new).
int star_entry(DefectStars& s, int u) {
  const auto first = s.star.begin() + s.start.back();
  const auto it = std::find(first, s.star.end(), u);
  if (it != s.star.end()) return static_cast<int>(it - s.star.begin());
  s.star.push_back(u);
  return static_cast<int>(s.star.size()) - 1;
}

}  // namespace

DefectStars defect_stars(const GroupMesh& g, const VertexFaces& incident,
                         const std::vector<char>& has_row, double weight) {
  std::map<int, double> patch_area;  // A_P of every patch (or solve group) of the group
  for (Eigen::Index f = 0; f < g.solve_faces; ++f)
    patch_area[g.face_unit[static_cast<size_t>(f)]] += face_area(g.V0, g.F, static_cast<int>(f));
  const std::vector<double> voronoi = vertex_angles(g.V0, g.F).area;  // A_v

  DefectStars s;
  for (size_t v = 0; v < has_row.size(); ++v) {
    if (!has_row[v] || !(voronoi[v] > 0)) continue;
    double area = 0;  // A_P: mean over the vertex's faces of their patch's area
    int faces = 0;
    s.star.push_back(static_cast<int>(v));
    for (int k = incident.start[v]; k < incident.start[v + 1]; ++k) {
      const int f = incident.faces[static_cast<size_t>(k)];
      for (int c = 0; c < 3; ++c) star_entry(s, g.F(f, c));
      if (f < g.solve_faces) {
        area += patch_area[g.face_unit[static_cast<size_t>(f)]];
        ++faces;
      }
    }
    s.vertex.push_back(static_cast<int>(v));
    s.start.push_back(static_cast<int>(s.star.size()));
    s.patch_area.push_back(area / std::max(faces, 1));
    s.root_area.push_back(std::sqrt(voronoi[v]));
  }
  s.weigh(weight);
  return s;
}

void DefectStars::weigh(double w_d) {
  weight.resize(vertex.size());
  for (size_t r = 0; r < vertex.size(); ++r) weight[r] = w_d * patch_area[r] / root_area[r];
}

DefectLinearisation linearise_defects(const DefectStars& rows, const GroupMesh& g,
                                      const VertexFaces& incident, const Positions& X,
                                      const VertexAngles& angles) {
  DefectLinearisation lin;
  lin.defect.resize(rows.vertex.size());
  lin.gradient.assign(rows.star.size(), Vec3::Zero());
  for (size_t r = 0; r < rows.vertex.size(); ++r) {
    const int v = rows.vertex[r];
    lin.defect[r] = angles.defect[static_cast<size_t>(v)];
    const int first = rows.start[r], last = rows.start[r + 1];
    const auto entry = [&](int u) {
      return static_cast<size_t>(std::find(rows.star.begin() + first, rows.star.begin() + last, u) -
                                 rows.star.begin());
    };
    for (int k = incident.start[static_cast<size_t>(v)];
         k < incident.start[static_cast<size_t>(v) + 1]; ++k) {
      const int f = incident.faces[static_cast<size_t>(k)];
      const int c = g.F(f, 0) == v ? 0 : g.F(f, 1) == v ? 1 : 2;
      const int j = g.F(f, (c + 1) % 3), l = g.F(f, (c + 2) % 3);
      const Vec3 xi = X.row(v).transpose();
      const Vec3 ej = X.row(j).transpose() - xi, el = X.row(l).transpose() - xi;
      const Vec3 cross = ej.cross(el);
      const double doubled_area = cross.norm();
      if (!(doubled_area > 0)) continue;  // a degenerate face: no direction to follow
      const Vec3 n = cross / doubled_area;
      const Vec3 dj = -n.cross(ej) / ej.squaredNorm();  // ∂θ/∂x_j
      const Vec3 dl = n.cross(el) / el.squaredNorm();   // ∂θ/∂x_l
      lin.gradient[entry(j)] -= dj;                     // ∇K_v = −Σ ∂θ/∂x
      lin.gradient[entry(l)] -= dl;
      lin.gradient[entry(v)] += dj + dl;
    }
  }
  return lin;
}

}  // namespace qd::approximate
