// Area-weighted moments of a set of face normals: Σa, Σa·n, Σa·n·nᵀ. Sums of disjoint sets add,
// so the moments of two charts give those of their union without visiting a face.
#pragma once

#include <Eigen/Core>

#include "common/mesh.h"
#include "segment/common_names.h"

namespace qd::segment {

struct NormalMoments {
  double area = 0.0;
  Vec3 sum = Vec3::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();

  void add(const Vec3& n, double a) {
    area += a;
    sum += a * n;
    outer += a * n * n.transpose();
  }
  NormalMoments& operator+=(const NormalMoments& o) {
    area += o.area;
    sum += o.sum;
    outer += o.outer;
    return *this;
  }
  // Area-weighted covariance of the normals (zero for an empty set).
  Eigen::Matrix3d covariance() const {
    if (area <= 0) return Eigen::Matrix3d::Zero();
    const Vec3 mean = sum / area;
    return outer / area - mean * mean.transpose();
  }
};

}  // namespace qd::segment
