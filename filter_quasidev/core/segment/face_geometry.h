// Per-face normal, area and centroid, computed once for the segmentation.
#pragma once

#include <vector>

#include "common/mesh.h"
#include "segment/common_names.h"

namespace qd::segment {

struct FaceGeometry {
  std::vector<Vec3> normal;  // unit
  std::vector<double> area;
  std::vector<Vec3> centroid;
  double total_area = 0.0;
};

// In parallel on up to `threads` threads; the result does not depend on their number.
FaceGeometry face_geometry(const Positions& V, const Triangles& F, int threads);

}  // namespace qd::segment
