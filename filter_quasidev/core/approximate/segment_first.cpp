#include "approximate/segment_first.h"

#include <algorithm>

#include "approximate/common_names.h"
#include "approximate/target_normals.h"
#include "common/error.h"
#include "common/metrics.h"
#include "segment/segment.h"

namespace qd::approximate {
namespace {

// Step 1 fits one Gauss-image curve to the whole mesh.
bool one_curve_fits(const Problem& p) {
  std::vector<Vec3> normals;
  std::vector<double> areas;
  for (Eigen::Index f = 0; f < p.F.rows(); ++f) {
    normals.push_back(face_normal(p.V, p.F, static_cast<int>(f)));
    areas.push_back(face_area(p.V, p.F, static_cast<int>(f)));
  }
  try {
    fit_model(normals, areas);  // the targets' projection (Step 1.5) would tell no more
    return true;
  } catch (const Error&) {
    return false;
  }
}

}  // namespace

SegmentFirstPlan plan_segment_first(const Problem& problem, const Topology& topology) {
  const SegmentFirst mode = problem.params.segment_first;
  if (!problem.patch.empty() || mode == SegmentFirst::Never) return {};
  if (mode == SegmentFirst::Always) return {true, "asked"};
  const bool closed = std::none_of(topology.boundary.begin(), topology.boundary.end(),
                                   [](char b) { return b != 0; });
  if (closed) return {true, "it is closed"};
  if (!one_curve_fits(problem)) return {true, "its normals fit no one Gauss-image curve"};
  return {};
}

Problem segmented(const Problem& problem) {
  segment::SegmentProblem s;
  s.V = problem.V;
  s.F = problem.F;
  s.params.max_error_deg = kSegmentFirstMaxErrorDeg;
  s.params.threads = problem.params.threads;
  const segment::SegmentResult r = segment::segment(s);
  Problem out = problem;
  out.patch = r.patch;
  out.params.seams = SeamMode::Free;
  return out;
}

}  // namespace qd::approximate
