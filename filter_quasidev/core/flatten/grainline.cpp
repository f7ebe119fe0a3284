#include "flatten/grainline.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace qd::flatten {

Eigen::Vector2d principal_axis(const Eigen::MatrixX2d& points) {
  const Eigen::MatrixX2d centred = points.rowwise() - points.colwise().mean();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(centred.transpose() * centred);
  return eigen.eigenvectors().col(1);  // eigenvalues ascend
}

Eigen::Vector2d grain_direction(const Positions& V, const Triangles& F, const Eigen::MatrixX2d& uv,
                                const Eigen::Vector3d& up) {
  const bool longest = up.isZero();  // the longest axis, pointing the way +y leans
  const Eigen::Vector3d unit_up = longest ? Eigen::Vector3d::UnitY() : up.normalized();
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double area = 0;
  for (int f = 0; f < F.rows(); ++f) {
    Eigen::Matrix<double, 3, 2> edges;  // 3D edges from corner 0
    Eigen::Matrix2d flat;               // the same on the piece
    for (int k = 0; k < 2; ++k) {
      edges.col(k) = (V.row(F(f, k + 1)) - V.row(F(f, 0))).transpose();
      flat.col(k) = (uv.row(F(f, k + 1)) - uv.row(F(f, 0))).transpose();
    }
    const Eigen::Matrix2d gram = edges.transpose() * edges;
    const double a = face_area(V, F, f);
    if (a <= 0 || gram.determinant() <= 0) continue;
    // flat · gram⁻¹ · edgesᵀ maps the face's edges onto the piece's and its normal to zero,
    // so applied to `up` it maps up's projection into the face's plane.
    sum += a * flat * gram.inverse() * (edges.transpose() * unit_up);
    area += a;
  }
  if (!longest && area > 0 && sum.norm() >= kWeakGrain * area) return sum.normalized();
  const Eigen::Vector2d axis = principal_axis(uv);
  return axis.dot(sum) < 0 ? Eigen::Vector2d(-axis) : axis;
}

}  // namespace qd::flatten
