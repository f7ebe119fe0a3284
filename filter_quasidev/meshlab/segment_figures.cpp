#include "segment_figures.h"

#include <algorithm>
#include <vector>

namespace qdml {

std::map<std::string, Figure> segment_figures(const qd::segment::SegmentResult& r) {
  using P = qd::segment::SegmentPatch;
  double worst = 0;
  int disks = 0, over = 0;
  for (const P& p : r.patches) {
    worst = std::max(worst, p.max_error_deg);
    disks += p.disk ? 1 : 0;
    over += p.over_limit != qd::segment::OverLimit::No ? 1 : 0;
  }
  return {
      {"patches", static_cast<int>(r.patches.size())},
      {"max_error_deg", worst},
      {"disks", disks},
      {"over_limit", over},
      {"rounds", r.rounds},
      {"warnings", static_cast<int>(r.warnings.size())},
      {"time_ms", r.time_ms},
      {"patch_faces", figure_list(r.patches, [](const P& p) { return p.faces; })},
      {"patch_area", figure_list(r.patches, [](const P& p) { return p.area; })},
      {"patch_max_error_deg", figure_list(r.patches, [](const P& p) { return p.max_error_deg; })},
      {"patch_rms_error_deg", figure_list(r.patches, [](const P& p) { return p.rms_error_deg; })},
      {"patch_boundary_loops", figure_list(r.patches, [](const P& p) { return p.boundary_loops; })},
      {"patch_disk", figure_list(r.patches, [](const P& p) { return p.disk ? 1 : 0; })},
      {"patch_over_limit",
       figure_list(r.patches,
                   [](const P& p) { return p.over_limit != qd::segment::OverLimit::No ? 1 : 0; })},
  };
}

}  // namespace qdml
