// Synthetic Gauss images with known skeleton curves for the Step 1 tests: samples along a
// spherical curve given in a frame (e1, e2, axis), with Gaussian angular noise, random areas
// and optional outliers. Deterministic (fixed seeds).
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "common/mesh.h"

namespace qd_test {

using namespace qd::common;

using qd::common::Vec3;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

struct Samples {
  std::vector<Vec3> normals;
  std::vector<double> areas;
};

// A rotation taking +z to `axis` (any such rotation; the tests only need a generic frame).
inline Eigen::Matrix3d frame_for(const Vec3& axis) {
  return Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), axis.normalized()).toRotationMatrix();
}

// Unit vector at angle `noise_rad` (per tangent component, Gaussian) around n.
inline Vec3 perturb(const Vec3& n, double noise_rad, std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, noise_rad);
  const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  return (n + g(rng) * t1 + g(rng) * t2).normalized();
}

// `count` samples of the curve t -> frame·(sinφ(t) cos t, sinφ(t) sin t, cosφ(t)), t uniform
// in [t0, t1], plus `outliers` uniform random unit vectors with small areas.
inline Samples curve_samples(const Eigen::Matrix3d& frame, double t0, double t1,
                             const std::function<double(double)>& phi_of_t, int count,
                             double noise_rad, int outliers = 0, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ut(t0, t1), area(0.5, 1.5);
  Samples s;
  for (int i = 0; i < count; ++i) {
    const double t = ut(rng), phi = phi_of_t(t);
    const Vec3 local(std::sin(phi) * std::cos(t), std::sin(phi) * std::sin(t), std::cos(phi));
    s.normals.push_back(perturb(frame * local, noise_rad, rng));
    s.areas.push_back(area(rng));
  }
  std::normal_distribution<double> g(0.0, 1.0);
  for (int i = 0; i < outliers; ++i) {
    s.normals.push_back(Vec3(g(rng), g(rng), g(rng)).normalized());
    s.areas.push_back(0.2 * area(rng));
  }
  return s;
}

// Normals of a cylinder with axis `axis` over azimuths [t0, t1]: a great-circle arc.
inline Samples cylinder(const Vec3& axis, double t0, double t1, int count, double noise_rad,
                        int outliers = 0) {
  return curve_samples(
      frame_for(axis), t0, t1, [](double) { return kPi / 2; }, count, noise_rad, outliers);
}

// Normals of a cone whose normals make angle `beta` with `axis`: a small circle.
inline Samples cone(const Vec3& axis, double beta, double t0, double t1, int count,
                    double noise_rad) {
  return curve_samples(
      frame_for(axis), t0, t1, [beta](double) { return beta; }, count, noise_rad);
}

// Angle (radians) between two unit vectors.
inline double angle(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// Random rotation (deterministic from the seed).
inline Eigen::Matrix3d random_rotation(unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
}

}  // namespace qd_test
