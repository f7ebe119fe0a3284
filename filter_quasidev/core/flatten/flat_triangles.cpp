#include "flatten/flat_triangles.h"

#include <cmath>

namespace qd::flatten {

FlatTriangles flat_triangles(const Positions& V, const Triangles& F) {
  const auto n = static_cast<size_t>(F.rows());
  FlatTriangles g;
  g.corner.resize(n);
  g.inverse_edges.resize(n);
  g.area.resize(F.rows());
  g.angle.resize(F.rows(), 3);
  g.half_cot.resize(F.rows(), 3);
  for (int f = 0; f < F.rows(); ++f) {
    const Vec3 a = V.row(F(f, 1)) - V.row(F(f, 0)), b = V.row(F(f, 2)) - V.row(F(f, 0));
    const double length = a.norm(), doubled_area = a.cross(b).norm();
    const double x2 = length > 0 ? a.dot(b) / length : 0.0,
                 y2 = length > 0 ? doubled_area / length : 0.0;
    Eigen::Matrix<double, 2, 3>& x = g.corner[f];
    x << 0, length, x2, 0, 0, y2;
    g.area(f) = 0.5 * doubled_area;
    Eigen::Matrix2d E;
    E << length, x2, 0, y2;
    g.inverse_edges[f] = doubled_area > 0 ? Eigen::Matrix2d(E.inverse()) : Eigen::Matrix2d::Zero();
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d p = x.col((k + 1) % 3) - x.col(k), q = x.col((k + 2) % 3) - x.col(k);
      const double cross = p.x() * q.y() - p.y() * q.x(), dot = p.dot(q);
      g.angle(f, k) = std::atan2(std::abs(cross), dot);
      g.half_cot(f, k) = doubled_area > 0 ? 0.5 * dot / cross : 0.0;
    }
  }
  return g;
}

Eigen::Matrix2d face_jacobian(const FlatTriangles& g, const Triangles& F,
                              const Eigen::MatrixX2d& uv, int f) {
  Eigen::Matrix2d U;
  U.col(0) = (uv.row(F(f, 1)) - uv.row(F(f, 0))).transpose();
  U.col(1) = (uv.row(F(f, 2)) - uv.row(F(f, 0))).transpose();
  return U * g.inverse_edges[f];
}

}  // namespace qd::flatten
