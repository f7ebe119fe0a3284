// Generated meshes with known flat patterns for the flattening tests.
#pragma once

#include <cmath>

#include "../grid_mesh.h"

namespace qd::test {

// Cylinder of radius r and height h, `columns` vertices around: a tube when `sweep` is a full
// turn, else an open strip. Quads are planar rectangles, so it is exactly developable: its
// development is a (columns·chord) × h rectangle.
inline GridMesh cylinder(int columns, int rows, double r, double h, double sweep = 2 * M_PI) {
  const bool tube = std::abs(sweep - 2 * M_PI) < 1e-12;
  return grid_mesh(columns, rows, tube, [&](int i, int j) {
    const double t = sweep * i / columns;
    return Vec3(r * std::cos(t), r * std::sin(t), h * j / rows);
  });
}

// Frustum of a cone: radius r0 at z = 0 to r1 at z = h. Quads are planar isosceles trapezoids,
// so it is exactly developable (into a sector of an annulus).
inline GridMesh cone(int columns, int rows, double r0, double r1, double h,
                     double sweep = 2 * M_PI) {
  const bool tube = std::abs(sweep - 2 * M_PI) < 1e-12;
  return grid_mesh(columns, rows, tube, [&](int i, int j) {
    const double t = sweep * i / columns, s = static_cast<double>(j) / rows, r = r0 + (r1 - r0) * s;
    return Vec3(r * std::cos(t), r * std::sin(t), h * s);
  });
}

// A spherical cap of the unit sphere up to polar angle `cap` (doubly curved), on a polar grid.
inline GridMesh spherical_cap(int columns, int rows, double cap) {
  GridMesh m = grid_mesh(columns, rows, true, [&](int i, int j) {
    const double t = 2 * M_PI * i / columns, p = cap * (j + 1) / (rows + 1);
    return Vec3(std::sin(p) * std::cos(t), std::sin(p) * std::sin(t), std::cos(p));
  });
  // Close the hole at the pole with a fan around a new pole vertex.
  const int pole = static_cast<int>(m.V.rows());
  m.V.conservativeResize(pole + 1, 3);
  m.V.row(pole) << 0, 0, 1;
  const int faces = static_cast<int>(m.F.rows());
  m.F.conservativeResize(faces + columns, 3);
  for (int i = 0; i < columns; ++i) m.F.row(faces + i) << pole, (i + 1) % columns, i;
  return m;
}

}  // namespace qd::test
