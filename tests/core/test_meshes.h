// Small generated meshes for the engine's tests.
#pragma once

#include <cmath>

#include "approximate/problem.h"
#include "grid_mesh.h"

namespace qd::test {

using namespace qd::approximate;
using namespace qd::common;

// The open cylinder of bumpy_cylinder() at angle t and height z.
inline Vec3 cylinder_point(double t, double z, double bump, double cone, double h) {
  const double d2 = std::pow(std::remainder(t - 1.0, 2 * M_PI), 2) + std::pow(z - h / 2, 2);
  const double r =
      1.0 + cone * z + bump * std::exp(-d2 / 0.18) +
      0.5 * bump *
          std::exp(-(std::pow(std::remainder(t + 2.0, 2 * M_PI), 2) + std::pow(z - h / 3, 2)) /
                   0.1);
  return Vec3(r * std::cos(t), r * std::sin(t), z);
}

// Open cylinder (axis z, radius 1, height h) of nu×nv quads split into triangles, with a smooth
// radial Gaussian bump of amplitude `bump` (0 = exactly developable up to discretisation) and an
// optional cone factor (radius grows by `cone`·z). Patch id = 0, or by angular sector when
// `sectors` > 1. Faces are oriented outward.
inline Problem bumpy_cylinder(int nu, int nv, double bump, double cone = 0.0, int sectors = 1,
                              double h = 2.0) {
  const GridMesh grid = grid_mesh(nu, nv, true, [&](int i, int j) {
    return cylinder_point(2 * M_PI * i / nu, h * j / nv, bump, cone, h);
  });
  Problem p;
  p.V = grid.V;
  p.F = grid.F;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int s = i * sectors / nu;  // the two triangles of quad (i, j)
      p.patch.push_back(s);
      p.patch.push_back(s);
    }
  if (sectors == 1) p.patch.clear();
  p.params.tolerance = 1.0;  // model units: generous
  return p;
}

// The same surface (height 2, no cone, one patch) with every interior grid vertex slid within it
// by up to `slide` of a cell each way (a fixed pseudo-random pattern), so that no edge follows a
// ruling: the curve targets' face normals are then out of reach (docs/robustness.md).
inline Problem irregular_cylinder(int nu, int nv, double bump, double slide) {
  const auto jitter = [](int i, int j, int k) {  // in [−1.5, 1.5], hence slide / 1.5 below
    return std::sin(12.9898 * i + 78.233 * j + 37.719 * k) * 0.5 + std::sin(3.1 * i * j + k);
  };
  Problem p = bumpy_cylinder(nu, nv, bump);
  const GridMesh grid = grid_mesh(nu, nv, true, [&](int i, int j) {
    const double s = j == 0 || j == nv ? 0.0 : slide / 1.5;
    return cylinder_point(2 * M_PI * (i + s * jitter(i, j, 0)) / nu,
                          2.0 * (j + s * jitter(i, j, 1)) / nv, bump, 0.0, 2.0);
  });
  p.V = grid.V;
  return p;
}

// A flat square (side 2, n×n quads) with two smooth Gaussian bumps, one out and one in, of
// height `bump`: the curve targets flatten it almost entirely.
inline Problem bumpy_plane(int n, double bump) {
  const GridMesh grid = grid_mesh(n, n, false, [&](int i, int j) {
    const double x = 2.0 * i / n, y = 2.0 * j / n;
    const double z = bump * (std::exp(-(std::pow(x - 0.7, 2) + std::pow(y - 0.8, 2)) / 0.1) -
                             std::exp(-(std::pow(x - 1.3, 2) + std::pow(y - 1.2, 2)) / 0.1));
    return Vec3(x, y, z);
  });
  Problem p;
  p.V = grid.V;
  p.F = grid.F;
  p.params.tolerance = 1.0;  // model units: generous
  return p;
}

}  // namespace qd::test
