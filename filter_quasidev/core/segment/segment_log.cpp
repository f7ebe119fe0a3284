// Report lines of the segmentation.
#include "segment/segment_log.h"

#include <algorithm>
#include <cmath>

#include "common/format_text.h"
#include "common/message_text.h"
#include "segment/common_names.h"

namespace qd::segment {

using common::format_text;

namespace {

double degrees(double radians) { return radians * 180.0 / M_PI; }

}  // namespace

const char* proxy_kind(const ConeProxy& proxy) {
  const double angle = degrees(proxy.angle);
  if (angle <= kKindToleranceDeg) return "plane";
  if (angle >= 90.0 - kKindToleranceDeg) return "cylinder";
  return "cone";
}

std::string over_limit_text(OverLimit over, const SegmentParams& q) {
  const std::string size = std::to_string(q.min_faces) + " faces";
  switch (over) {
    case OverLimit::No:
      return "";
    case OverLimit::SmallestSize:
      return "a part too curved to fit within it at the smallest patch size (" + size +
             "); lower the smallest patch size or raise the largest fit error";
    case OverLimit::SmallPart:
      return "it took in a neighbouring part below the smallest patch size (" + size +
             ") that fit nowhere; lower the smallest patch size or raise the largest fit error";
    case OverLimit::TargetCount:
      return "merged to reach the target of " + std::to_string(q.target_patches) +
             " patches; raise the target patch count";
  }
  return "";
}

std::string patch_line(int id, const SegmentPatch& p, const SegmentParams& q) {
  std::string line = format_text(
      "Patch %d: %d faces, area %.6g, %s (axis %.4f %.4f %.4f, angle %.2f deg), fit "
      "error max %.2f deg, rms %.2f deg, %d boundary loop%s, %s",
      id, p.faces, p.area, proxy_kind(p.proxy), p.proxy.axis.x(), p.proxy.axis.y(),
      p.proxy.axis.z(), degrees(p.proxy.angle), p.max_error_deg, p.rms_error_deg, p.boundary_loops,
      p.boundary_loops == 1 ? "" : "s", p.disk ? "a disk" : "not a disk (needs a cut to flatten)");
  if (p.kept) line += ", kept whole";
  if (p.over_limit != OverLimit::No) {
    line += format_text("; over the %.4g deg limit: ", q.max_error_deg) +
            over_limit_text(p.over_limit, q);
  }
  return line + ".";
}

std::vector<std::string> segment_warnings(int nonmanifold_edges, int misoriented_edges,
                                          const SegmentResult& r, const SegmentParams& q) {
  std::vector<std::string> out;
  if (nonmanifold_edges > 0)
    out.push_back(count_text(nonmanifold_edges, "non-manifold edge", "non-manifold edges") +
                  " (more than two faces) kept as patch borders; to let patches cross them, "
                  "repair them (MeshLab: Filters > Cleaning and Repairing > Repair non Manifold "
                  "Edges).");
  if (misoriented_edges > 0)
    out.push_back(count_text(misoriented_edges, "edge joins", "edges join") +
                  " faces of opposite orientation: kept as patch borders so every patch is "
                  "consistently oriented; to let patches cross them, re-orient the faces "
                  "(MeshLab: Filters > Normals, Curvatures and Orientation > Re-Orient all faces "
                  "coherently).");
  int over = 0, first_over = -1, small = 0, first_small = -1;
  for (size_t id = 0; id < r.patches.size(); ++id) {
    if (r.patches[id].over_limit != OverLimit::No && over++ == 0) first_over = int(id);
    if (r.patches[id].faces < q.min_faces && small++ == 0) first_small = int(id);
  }
  if (over > 0)
    out.push_back(count_text(over, "patch is", "patches are") + " over the largest fit error (" +
                  "first: patch " + std::to_string(first_over) + "); their lines say why.");
  const int made = static_cast<int>(r.patches.size());
  if (q.target_patches > 0 && made != q.target_patches)
    out.push_back("Made " + count_text(made, "patch", "patches") + ", not the target " +
                  std::to_string(q.target_patches) +
                  ": patches never join across kept borders or separate components, and a "
                  "patch is split only into halves of at least the smallest size.");
  if (small > 0)
    out.push_back(count_text(small, "patch is", "patches are") + " below the smallest size (" +
                  "first: patch " + std::to_string(first_small) + ", " +
                  count_text(r.patches[first_small].faces, "face", "faces") +
                  ") because the part between kept borders is that small.");
  return out;
}

std::vector<std::string> segment_log(const SegmentResult& r, int faces, const SegmentParams& q) {
  std::vector<std::string> log = r.warnings;
  double worst = 0;
  int disks = 0;
  for (size_t id = 0; id < r.patches.size(); ++id) {
    log.push_back(patch_line(static_cast<int>(id), r.patches[id], q));
    worst = std::max(worst, r.patches[id].max_error_deg);
    disks += r.patches[id].disk;
  }
  log.push_back(
      format_text("Segmented %d faces into %d patches (%d disks) in %d rounds; largest fit error "
                  "%.2f deg (limit %.4g deg); %.0f ms.",
                  faces, static_cast<int>(r.patches.size()), disks, r.rounds, worst,
                  q.max_error_deg, r.time_ms));
  return log;
}

}  // namespace qd::segment
