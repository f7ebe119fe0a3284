// Charts as sets of faces, after growing: what merging works on and the report describes.
#pragma once

#include <vector>

#include "segment/cone_fit.h"
#include "segment/face_geometry.h"
#include "segment/segment_result.h"

namespace qd::segment {

struct Partition {
  std::vector<int> label;               // per face: chart index, or kOutside (chart.h)
  std::vector<std::vector<int>> faces;  // per chart, ascending; empty once merged away
  std::vector<ConeFit> fit;             // per chart
  std::vector<OverLimit> over;          // per chart: the reason if fit.max_error > limit
  std::vector<char> kept;               // per chart: a region of the input kept whole
};

// The faces of each chart of `label` (count charts), ascending.
std::vector<std::vector<int>> faces_by_chart(const std::vector<int>& label, int count);

// The faces whose label is `value`, ascending.
std::vector<int> faces_labelled(const std::vector<int>& label, int value);

// The area of a set of faces.
double faces_area(const FaceGeometry& g, const std::vector<int>& faces);

}  // namespace qd::segment
