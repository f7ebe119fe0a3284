// Small generated meshes for the engine's tests.
#pragma once

#include <cmath>

#include "approximate/problem.h"
#include "grid_mesh.h"

namespace qd::test {

using namespace qd::approximate;
using namespace qd::common;

// Open cylinder (axis z, radius 1, height h) of nu×nv quads split into triangles, with a smooth
// radial Gaussian bump of amplitude `bump` (0 = exactly developable up to discretisation) and an
// optional cone factor (radius grows by `cone`·z). Patch id = 0, or by angular sector when
// `sectors` > 1. Faces are oriented outward.
inline Problem bumpy_cylinder(int nu, int nv, double bump, double cone = 0.0, int sectors = 1,
                              double h = 2.0) {
  const GridMesh grid = grid_mesh(nu, nv, true, [&](int i, int j) {
    const double t = 2 * M_PI * i / nu, z = h * j / nv;
    const double d2 = std::pow(std::remainder(t - 1.0, 2 * M_PI), 2) + std::pow(z - h / 2, 2);
    const double r =
        1.0 + cone * z + bump * std::exp(-d2 / 0.18) +
        0.5 * bump *
            std::exp(-(std::pow(std::remainder(t + 2.0, 2 * M_PI), 2) + std::pow(z - h / 3, 2)) /
                     0.1);
    return Vec3(r * std::cos(t), r * std::sin(t), z);
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
