// Developability and shape figures (docs/design.md "Metrics"): angle defect, mixed Voronoi area,
// K(v) (Eq. 18), OBD (Defs. 2–3), shape difference (Defs. 4–5), displacement.
#include "common/metrics.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

#include "common/error.h"

namespace qd::common {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2 * kPi;

// Per-corner quantities of one face: corner k sits at F(f, k).
struct Corners {
  double doubled_area = 0;  // |(v2 − v1) × (v3 − v1)|
  double dot[3] = {0, 0, 0};  // (v_{k+1} − v_k)·(v_{k+2} − v_k): cos of the corner angle, unscaled
  double len2[3] = {0, 0, 0};  // |v_{k+1} − v_k|²: squared length of the edge leaving corner k
};

Corners corners_of(const Positions& V, const Triangles& F, int f) {
  Corners c;
  const Vec3 p[3] = {V.row(F(f, 0)).transpose(), V.row(F(f, 1)).transpose(),
                     V.row(F(f, 2)).transpose()};
  c.doubled_area = (p[1] - p[0]).cross(p[2] - p[0]).norm();
  for (int k = 0; k < 3; ++k) {
    const Vec3 next = p[(k + 1) % 3] - p[k];
    const Vec3 prev = p[(k + 2) % 3] - p[k];
    c.dot[k] = next.dot(prev);
    c.len2[k] = next.squaredNorm();
  }
  return c;
}

// Interior angle θ at corner k: atan2(|e × e'|, e·e') = π/2 − atan(cot θ), the cheaper call;
// 0 or π on a zero-area face.
double corner_angle(const Corners& c, int k) {
  if (!(c.doubled_area > 0)) return c.dot[k] < 0 ? kPi : 0.0;
  return kPi / 2 - std::atan(c.dot[k] / c.doubled_area);
}

// Share of the face's area given to corner k (Meyer et al. 2003, mixed area): the Voronoi
// region 1/8·(|PR|² cot Q + |PQ|² cot R) for a non-obtuse face, else area/2 at the obtuse
// corner and area/4 at the others. Zero for a zero-area face.
double corner_mixed_area(const Corners& c, int k) {
  if (c.doubled_area <= 0) return 0.0;
  const double area = 0.5 * c.doubled_area;
  const int obtuse = c.dot[0] < 0 ? 0 : c.dot[1] < 0 ? 1 : c.dot[2] < 0 ? 2 : -1;
  if (obtuse >= 0) return obtuse == k ? area / 2 : area / 4;
  const int q = (k + 1) % 3;
  const int r = (k + 2) % 3;
  const double cot_q = c.dot[q] / c.doubled_area;
  const double cot_r = c.dot[r] / c.doubled_area;
  // |PR|² is the edge leaving r (r → P), |PQ|² the edge leaving P (P → Q).
  return (c.len2[r] * cot_q + c.len2[k] * cot_r) / 8.0;
}

// K(v) = (2π − Σθ_j)/A_v (Eq. 18); 0 where the mixed area vanishes.
double curvature(double defect, double area) { return area > 0 ? defect / area : 0.0; }

}  // namespace

VertexAngles vertex_angles(const Positions& V, const Triangles& F) {
  const auto n = static_cast<size_t>(V.rows());
  VertexAngles out{std::vector<double>(n, kTwoPi), std::vector<double>(n, 0.0)};
  for (int f = 0; f < F.rows(); ++f) {
    const Corners c = corners_of(V, F, f);
    // The third interior angle from θ_0 + θ_1 + θ_2 = π.
    const double t0 = corner_angle(c, 0), t1 = corner_angle(c, 1);
    const double theta[3] = {t0, t1, kPi - t0 - t1};
    for (int k = 0; k < 3; ++k) {
      const auto v = static_cast<size_t>(F(f, k));
      out.defect[v] -= theta[k];
      out.area[v] += corner_mixed_area(c, k);
    }
  }
  return out;
}

std::vector<double> gaussian_curvature(const VertexAngles& angles,
                                       const std::vector<char>& interior) {
  assert(angles.area.size() == angles.defect.size());
  std::vector<double> k(angles.defect.size(), 0.0);
  for (size_t v = 0; v < k.size(); ++v)
    if (v < interior.size() && interior[v]) k[v] = curvature(angles.defect[v], angles.area[v]);
  return k;
}

double orientation_developability(const Positions& V, const Triangles& F,
                                  const std::vector<int>& faces, const std::vector<Vec3>& targets) {
  if (targets.size() != faces.size())
    throw Error("internal error: " + std::to_string(targets.size()) + " target normals for " +
                std::to_string(faces.size()) + " faces; please report this bug");
  double total = 0.0;  // D(P), Eq. 3
  for (size_t i = 0; i < faces.size(); ++i) {
    const int f = faces[i];
    for (int k = 0; k < 3; ++k) {  // d_k = |n_t·(v'_{k+1} − v'_k)|, Eqs. 1–2
      const Vec3 edge = (V.row(F(f, (k + 1) % 3)) - V.row(F(f, k))).transpose();
      total += std::abs(targets[i].dot(edge));
    }
  }
  return total;
}

double shape_difference(const Positions& V0, const Positions& V, const Triangles& F,
                        const std::vector<int>& faces) {
  double total = 0.0;  // S(P), Eq. 7
  for (const int f : faces) {
    const Vec3 d1 = (V.row(F(f, 0)) - V0.row(F(f, 0))).transpose();  // v'_i − v_i
    const Vec3 d2 = (V.row(F(f, 1)) - V0.row(F(f, 1))).transpose();
    const Vec3 d3 = (V.row(F(f, 2)) - V0.row(F(f, 2))).transpose();
    const double s1 = (d2 - d1).squaredNorm();             // Eq. 5
    const double s2 = (d3 - d1).squaredNorm();             // Eq. 5
    const double s3 = (d1 + d2 + d3).squaredNorm() / 3.0;  // Eq. 6
    total += s1 + s2 + s3;                                 // s(t), Eq. 4
  }
  return total;
}

Figures measure(const VertexAngles& angles, const Positions& V0, const Positions& V,
                const Triangles& F, const std::vector<int>& vertices, const std::vector<int>& faces,
                const std::vector<Vec3>& targets, const std::vector<int>& moved) {
  Figures out;
  for (const int v : vertices) {
    const double defect = angles.defect[static_cast<size_t>(v)];
    const double k = std::abs(curvature(defect, angles.area[static_cast<size_t>(v)]));
    out.g_abd += k;
    out.angle_defect += std::abs(defect);
    out.max_abs_k = std::max(out.max_abs_k, k);
  }

  if (!targets.empty()) out.obd = orientation_developability(V, F, faces, targets);
  out.shape = shape_difference(V0, V, F, faces);

  for (const int v : moved) {
    const double d = (V.row(v) - V0.row(v)).norm();
    out.max_disp = std::max(out.max_disp, d);
    out.mean_disp += d;
  }
  if (!moved.empty()) out.mean_disp /= static_cast<double>(moved.size());
  return out;
}

}  // namespace qd::common
