// A regular grid of quads split into triangles, for the generated test meshes.
#pragma once

#include <vector>

#include "common/mesh.h"

namespace qd::test {

using namespace qd::common;

struct GridMesh {
  Positions V;
  Triangles F;
  std::vector<int> patch;
};

// (columns + 1) × (rows + 1) vertices at point(i, j), quads split along one diagonal, faces
// running counter-clockwise in the (i, j) parameter plane. closed_i: column `columns` is column 0
// (a tube), so there are only `columns` columns of vertices.
template <typename Point>
GridMesh grid_mesh(int columns, int rows, bool closed_i, const Point& point) {
  GridMesh m;
  const int width = closed_i ? columns : columns + 1;
  m.V.resize(width * (rows + 1), 3);
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < width; ++i) m.V.row(j * width + i) = point(i, j).transpose();
  m.F.resize(2 * columns * rows, 3);
  int f = 0;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const int a = j * width + i, b = j * width + (i + 1) % width, c = a + width, d = b + width;
      m.F.row(f++) << a, b, d;
      m.F.row(f++) << a, d, c;
    }
  return m;
}

}  // namespace qd::test
