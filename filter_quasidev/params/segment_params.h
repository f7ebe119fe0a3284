// The parameters of the segmentation, declared once (see param.h).
#pragma once

#include <vector>

#include "param.h"
#include "segment_settings.h"

namespace qd::params {

const std::vector<Param<SegmentSettings>>& segment_params();

}  // namespace qd::params
