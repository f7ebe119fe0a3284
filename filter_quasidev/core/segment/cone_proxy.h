// The developable proxy of a chart in D-Charts (Julius, Kraevoy, Sheffer 2005): a cone given by
// its unit axis N and apex angle θ, whose surface normals all make the angle θ with N. θ = 0 is
// a plane (normal N), θ = 90° a cylinder (axis N); any other θ a cone. A face fits the proxy as
// well as its normal's angle to N is close to θ.
#pragma once

#include <algorithm>
#include <cmath>

#include "common/mesh.h"
#include "segment/common_names.h"

namespace qd::segment {

struct ConeProxy {
  Vec3 axis = Vec3::UnitZ();
  double angle = 0.0;  // radians, in [0, π/2]: the axis points to the side of the normals
};

// Angle between unit vectors a and b, radians.
inline double angle_between(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a.dot(b), -1.0, 1.0));
}

// Fit error of a face with unit normal n: |∠(n, N) − θ|, radians.
inline double cone_deviation(const ConeProxy& cone, const Vec3& n) {
  return std::abs(angle_between(n, cone.axis) - cone.angle);
}

// The plane with normal n (a new chart's proxy before its first fit).
inline ConeProxy plane_proxy(const Vec3& n) { return ConeProxy{n, 0.0}; }

}  // namespace qd::segment
