// Input of the segmentation: a triangle mesh, optional existing patches and selected faces, and
// the parameters.
#pragma once

#include <vector>

#include "common/mesh.h"
#include "segment/common_names.h"
#include "segment/segment_params.h"

namespace qd::segment {

struct SegmentProblem {
  Positions V;
  Triangles F;
  // Patch id per face, or empty. An existing patch is a region of its own: patches never cross
  // its border, it is kept whole where its faces fit one cone within the limit, and only the
  // patches too far from developable are split.
  std::vector<int> patch;
  // Per face, 1 = selected, or empty. The border between selected and unselected faces is kept:
  // no patch crosses it.
  std::vector<char> selected;
  SegmentParams params;
};

}  // namespace qd::segment
