// A chart while the segmentation grows it: its seed face, its proxy and what the growing cost
// needs to know about it.
#pragma once

#include "segment/cone_proxy.h"

namespace qd::segment {

struct Chart {
  int seed = -1;
  ConeProxy proxy;
  double area_hint = 0.0;  // A(C) of the compactness term: the chart's area at its last growth
};

// Labels of faces in an assignment other than chart indices.
constexpr int kFree = -1;     // not in a chart yet
constexpr int kOutside = -2;  // not segmented here (a region kept whole)

}  // namespace qd::segment
