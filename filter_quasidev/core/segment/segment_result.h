// Output of the segmentation: a patch id per face and a report per patch.
#pragma once

#include <string>
#include <vector>

#include "segment/cone_proxy.h"

namespace qd::segment {

// Why a patch's fit error is over the limit.
enum class OverLimit {
  No,
  SmallestSize,  // a part too curved to fit within the limit at the smallest patch size, made
                 // a patch of that size from smaller charts or its neighbours' faces
  SmallPart,     // it took in a neighbouring part below the smallest size that fit nowhere
  TargetCount,   // merged over the limit to reach the wanted number of patches
};

struct SegmentPatch {
  int faces = 0;
  double area = 0.0;
  ConeProxy proxy;             // the fitted developable: plane, cylinder or cone (cone_proxy.h)
  double max_error_deg = 0.0;  // largest angle of a face normal to the cone
  double rms_error_deg = 0.0;  // area-weighted root mean square of the same
  int boundary_loops = 0;
  int euler = 0;          // V − E + F of the patch
  bool disk = false;      // Euler characteristic 1 and one boundary loop: flattens uncut
  bool kept = false;      // an input region (existing patch or component) kept whole
  int source_patch = -1;  // the input patch id of its faces, −1 without input patch ids
  OverLimit over_limit = OverLimit::No;
};

struct SegmentResult {
  std::vector<int> patch;             // per face, 0 … k−1; each patch is edge-connected
  std::vector<SegmentPatch> patches;  // per patch id, numbered in the order of lowest face
  int rounds = 0;                     // growing rounds of the Lloyd iteration
  double time_ms = 0.0;
  std::vector<std::string> warnings;  // parts of the input handled specially, and what to do
  std::vector<std::string> log;       // the warnings, one line per patch, a summary
};

}  // namespace qd::segment
