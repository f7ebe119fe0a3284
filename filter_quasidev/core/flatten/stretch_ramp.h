// The colour ramp of the per-face signed stretch (face_distortion.h) that every front end shows:
// symmetric about 0, so green is no stretch, blue stretched and red compressed, over the 98th
// percentile of |stretch| but at least ±kStretchRampFloor, so that a development exact to that
// reads uniformly green instead of colouring round-off.
#pragma once

#include <vector>

#include "common/quality_range.h"
#include "flatten/common_names.h"

namespace qd::flatten {

constexpr double kStretchRampFloor =
    1e-3;  // 0.1 %, the accuracy issue 14 asks of developable patches

QualityRange stretch_ramp_range(const std::vector<double>& stretch);

}  // namespace qd::flatten
