// The figures a run of the segmentation returns (pymeshlab: the dict of apply_filter): the patch
// count, the largest fit error, disks, rounds and time, and per patch (lists in patch id order)
// faces, area, fit error max/rms in degrees, boundary loops, disk (1/0) and over the limit (1/0).
// pymeshlab drops string values, so the warnings are counted; their text is in the log.
#pragma once

#include <map>
#include <string>

#include "filter_table.h"
#include "segment/segment_result.h"

namespace qdml {

std::map<std::string, Figure> segment_figures(const qd::segment::SegmentResult& r);

}  // namespace qdml
