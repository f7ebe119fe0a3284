#include "flatten/stretch_ramp.h"

namespace qd::flatten {

QualityRange stretch_ramp_range(const std::vector<double>& stretch) {
  return symmetric_quality_range(stretch, kStretchRampFloor);
}

}  // namespace qd::flatten
