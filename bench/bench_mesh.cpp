#include "bench_mesh.h"

#include <algorithm>
#include <cmath>

namespace qd::bench {

io::MeshDocument curved_sheet(long triangles, int patches) {
  const double quads = static_cast<double>(triangles) / 2.0;
  const int columns = std::max(2, static_cast<int>(std::lround(std::sqrt(quads))));
  const int rows = std::max(2, static_cast<int>(std::ceil(quads / columns)));
  const double pi = std::acos(-1.0), angle = pi / 2, height = angle;  // arc length = height
  const double edge = height / rows, bump = 0.3 * edge;
  io::MeshDocument mesh;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i) {
      const double u = static_cast<double>(i) / columns, v = static_cast<double>(j) / rows;
      const double r = 1.0 + bump * std::sin(6 * pi * u) * std::sin(6 * pi * v);
      mesh.positions.push_back({r * std::cos(angle * u), r * std::sin(angle * u), height * v});
    }
  const auto at = [&](int i, int j) { return j * (columns + 1) + i; };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const int band = std::min(patches - 1, j * patches / rows);
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      mesh.patch.push_back(band);
      mesh.patch.push_back(band);
    }
  if (patches <= 1) mesh.patch.clear();
  return mesh;
}

namespace {

// Two triangles per quad (i, j) of a grid of `around` × `rows` quads closed around i, with
// vertex at(i, j).
template <typename At>
void add_closed_quads(io::MeshDocument& mesh, int around, int rows, const At& at) {
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < around; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
}

}  // namespace

io::MeshDocument noisy_tube(long triangles) {
  const double quads = static_cast<double>(triangles) / 2.0;
  const int around = std::max(3, static_cast<int>(std::lround(std::sqrt(quads))));
  const int rows = std::max(1, static_cast<int>(std::lround(quads / around)));
  const double pi = std::acos(-1.0), height = 2 * pi, edge = height / rows;
  unsigned long long state = 88172645463325252ULL;  // xorshift64: the same noise every run
  const auto noise = [&] {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return static_cast<double>(state % 2001) / 1000.0 - 1.0;  // in [−1, 1]
  };
  io::MeshDocument mesh;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2 * pi * i / around, r = 1.0 + 0.1 * edge * noise();
      mesh.positions.push_back({r * std::cos(a), r * std::sin(a), edge * j});
    }
  add_closed_quads(mesh, around, rows, [&](int i, int j) { return j * around + i % around; });
  return mesh;
}

io::MeshDocument torus(long triangles) {
  const int tube =
      std::max(3, static_cast<int>(std::lround(std::sqrt(static_cast<double>(triangles) / 4.0))));
  const int around = 2 * tube;
  const double pi = std::acos(-1.0);
  io::MeshDocument mesh;
  for (int j = 0; j < tube; ++j)
    for (int i = 0; i < around; ++i) {
      const double u = 2 * pi * i / around, v = 2 * pi * j / tube, r = 2.0 + std::cos(v);
      mesh.positions.push_back({r * std::cos(u), r * std::sin(u), std::sin(v)});
    }
  add_closed_quads(mesh, around, tube,
                   [&](int i, int j) { return (j % tube) * around + i % around; });
  return mesh;
}

}  // namespace qd::bench
