// Face normals, areas and centroids in parallel ranges.
#include "segment/face_geometry.h"

#include "common/parallel_for.h"
#include "segment/common_names.h"

namespace qd::segment {

FaceGeometry face_geometry(const Positions& V, const Triangles& F, int threads) {
  const auto n = static_cast<size_t>(F.rows());
  FaceGeometry g;
  g.normal.resize(n);
  g.area.resize(n);
  g.centroid.resize(n);
  parallel_ranges(n, static_cast<size_t>(threads), kRangeChunk, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const int f = static_cast<int>(i);
      g.normal[i] = face_normal(V, F, f);
      g.area[i] = face_area(V, F, f);
      g.centroid[i] = (V.row(F(f, 0)) + V.row(F(f, 1)) + V.row(F(f, 2))).transpose() / 3.0;
    }
  });
  for (const double a : g.area) g.total_area += a;
  return g;
}

}  // namespace qd::segment
