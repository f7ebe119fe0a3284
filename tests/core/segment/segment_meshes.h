// Generated meshes for the segmentation tests: surfaces made of known developable pieces
// (planes, cylinders, cones) welded at shared vertices, each triangle tagged with its piece.
#pragma once

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

#include "segment/segment_problem.h"

namespace qd::test {

using namespace qd::common;
using namespace qd::segment;

class MeshBuilder {
 public:
  using Surface = std::function<Vec3(double u, double v)>;

  // An nu × nv grid of f over [0,1]², two triangles per quad, oriented along ∂f/∂u × ∂f/∂v,
  // tagged `piece`. Vertices at the same position (to 1e-9) are one vertex; triangles that
  // collapse (a disc's centre) are dropped.
  void grid(const Surface& f, int nu, int nv, int piece) {
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) {
        const int a = vertex(f(double(i) / nu, double(j) / nv));
        const int b = vertex(f(double(i + 1) / nu, double(j) / nv));
        const int c = vertex(f(double(i + 1) / nu, double(j + 1) / nv));
        const int d = vertex(f(double(i) / nu, double(j + 1) / nv));
        triangle(a, b, c, piece);
        triangle(a, c, d, piece);
      }
  }

  void triangle(int a, int b, int c, int piece) {
    if (a == b || b == c || c == a) return;
    triangles_.push_back({a, b, c});
    piece_.push_back(piece);
  }

  int vertex(const Vec3& p) {
    const std::array<long long, 3> key = {std::llround(p.x() * 1e9), std::llround(p.y() * 1e9),
                                          std::llround(p.z() * 1e9)};
    const auto [it, added] = index_.emplace(key, static_cast<int>(points_.size()));
    if (added) points_.push_back(p);
    return it->second;
  }

  SegmentProblem problem() const {
    SegmentProblem p;
    p.V.resize(static_cast<Eigen::Index>(points_.size()), 3);
    for (size_t v = 0; v < points_.size(); ++v) p.V.row(static_cast<Eigen::Index>(v)) = points_[v];
    p.F.resize(static_cast<Eigen::Index>(triangles_.size()), 3);
    for (size_t f = 0; f < triangles_.size(); ++f)
      for (int k = 0; k < 3; ++k) p.F(static_cast<Eigen::Index>(f), k) = triangles_[f][k];
    return p;
  }
  const std::vector<int>& pieces() const { return piece_; }

 private:
  std::vector<Vec3> points_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<int> piece_;
  std::map<std::array<long long, 3>, int> index_;
};

inline Vec3 ring(double u, double radius, double z) {
  return {radius * std::cos(2 * M_PI * u), radius * std::sin(2 * M_PI * u), z};
}

// Closed: a cylinder of radius 1 and height 2 (piece 0), a top disc (1) and a bottom disc (2).
inline MeshBuilder capped_cylinder(int around = 48, int up = 16, int rings = 6) {
  MeshBuilder b;
  b.grid([](double u, double v) { return ring(u, 1.0, 2 * v); }, around, up, 0);
  b.grid([](double u, double v) { return ring(u, 1.0 - v, 2.0); }, around, rings, 1);
  b.grid([](double u, double v) { return ring(u, v, 0.0); }, around, rings, 2);
  return b;
}

// Open: a cylinder of radius 1 from z = 0 to 1 (piece 0) under a cone frustum from radius 1 at
// z = 1 to radius 0.25 at z = 1.75 (piece 1), whose normals make about 45° with the axis: one
// cone would miss both by about 22.5°, more than the default limit, and the edge between them
// is no crease.
inline MeshBuilder cone_on_cylinder(int around = 48, int up = 12) {
  MeshBuilder b;
  b.grid([](double u, double v) { return ring(u, 1.0, v); }, around, up, 0);
  b.grid([](double u, double v) { return ring(u, 1.0 - 0.75 * v, 1.0 + 0.75 * v); }, around, up, 1);
  return b;
}

// Closed: the cube [−1, 1]³, each side an n × n grid (pieces 0 … 5).
inline MeshBuilder cube(int n = 10) {
  MeshBuilder b;
  const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ();
  const std::array<std::array<Vec3, 3>, 6> sides = {
      {{x, y, z}, {-x, z, y}, {y, z, x}, {-y, x, z}, {z, x, y}, {-z, y, x}}};  // normal, ∂u, ∂v
  for (int s = 0; s < 6; ++s) {
    const auto& [normal, du, dv] = sides[s];
    b.grid([&](double u, double v) -> Vec3 { return normal + (2 * u - 1) * du + (2 * v - 1) * dv; },
           n, n, s);
  }
  return b;
}

// The square [−1, 1]² (n × n quads) with a round bump z = height·exp(−r²/0.04) at its centre:
// doubly curved in a few dozen faces. height 0: a flat square.
inline MeshBuilder bumped_plane(int n = 20, double height = 0.5) {
  MeshBuilder b;
  b.grid(
      [&](double u, double v) -> Vec3 {
        const double x = 2 * u - 1, y = 2 * v - 1;
        return {x, y, height * std::exp(-(x * x + y * y) / 0.04)};
      },
      n, n, 0);
  return b;
}

// Three flat pages (pieces 0, 1, 2) sharing their spine, the segment from (0,0,0) to (0,0,1):
// every spine edge has three faces.
inline MeshBuilder book(int n = 6) {
  MeshBuilder b;
  for (int page = 0; page < 3; ++page) {
    const double angle = 2 * M_PI * page / 3;
    const Vec3 out(std::cos(angle), std::sin(angle), 0.0);
    b.grid([&](double u, double v) -> Vec3 { return u * out + Vec3(0, 0, v); }, n, n, page);
  }
  return b;
}

// Closed torus (radii 2 and 1) of 2·around·tube triangles: doubly curved everywhere.
inline MeshBuilder torus(int around = 64, int tube = 32) {
  MeshBuilder b;
  b.grid(
      [](double u, double v) -> Vec3 {
        const double r = 2.0 + std::cos(2 * M_PI * v);
        return {r * std::cos(2 * M_PI * u), r * std::sin(2 * M_PI * u), std::sin(2 * M_PI * v)};
      },
      around, tube, 0);
  return b;
}

}  // namespace qd::test
