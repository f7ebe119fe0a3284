// What a user sets for the segmentation, in every front end: the engine's parameters and what
// the input's patches and selection mean. segment_params.cpp declares each field.
#pragma once

#include "segment/segment_params.h"

namespace qd::params {

using segment::SegmentParams;

struct SegmentSettings {
  SegmentParams engine;
  bool keep_patches = false;     // the input's patch ids are patches, kept where they fit
  bool selection_border = true;  // the border of the face selection stays a patch border
};

}  // namespace qd::params
