#include "flatten/boundary_curve.h"

#include <Eigen/LU>
#include <cmath>

namespace qd::flatten {

Eigen::MatrixX2d closed_boundary_curve(const Eigen::VectorXd& lengths,
                                       const Eigen::VectorXd& turning) {
  const Eigen::Index m = lengths.size();
  Eigen::Matrix2Xd T(2, m);
  double phi = 0;
  for (Eigen::Index i = 0; i < m; ++i) {
    phi += turning(i);
    T.col(i) << std::cos(phi), std::sin(phi);
  }
  const Eigen::Matrix2Xd TN = T * lengths.asDiagonal();  // T N⁻¹
  const Eigen::Matrix2d gram = TN * T.transpose();
  Eigen::VectorXd closing = lengths;
  if (std::abs(gram.determinant()) > 0)  // a curve not all along one line
    closing -= TN.transpose() * gram.inverse() * (T * lengths);
  Eigen::MatrixX2d curve(m, 2);
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  for (Eigen::Index i = 0; i < m; ++i) {
    curve.row(i) = at.transpose();
    at += closing(i) * T.col(i);
  }
  return curve;
}

}  // namespace qd::flatten
