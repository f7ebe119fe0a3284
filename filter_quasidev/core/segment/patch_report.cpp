// The per-patch report: ids, sizes, cones, fit errors in degrees, topology, provenance.
#include "segment/patch_report.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "segment/patch_topology.h"

namespace qd::segment {

SegmentResult patch_report(const Partition& p, const SegmentProblem& problem,
                           const FaceGeometry& g) {
  assert(p.fit.size() == p.faces.size() && p.over.size() == p.faces.size() &&
         p.kept.size() == p.faces.size());
  std::vector<int> order;
  for (size_t c = 0; c < p.faces.size(); ++c)
    if (!p.faces[c].empty()) order.push_back(static_cast<int>(c));
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return p.faces[a].front() < p.faces[b].front(); });
  SegmentResult r;
  r.patch.assign(p.label.size(), -1);
  for (size_t id = 0; id < order.size(); ++id)
    for (const int f : p.faces[order[id]]) r.patch[f] = static_cast<int>(id);
  // The charts partition the faces: every face has its patch.
  assert(std::find(r.patch.begin(), r.patch.end(), -1) == r.patch.end());
  const int count = static_cast<int>(order.size());
  const std::vector<PatchTopology> topology =
      patch_topology(problem.F, problem.V.rows(), r.patch, count);
  const double limit = problem.params.max_error_deg * M_PI / 180.0;
  for (int id = 0; id < count; ++id) {
    const int c = order[id];
    SegmentPatch s;
    s.faces = topology[id].faces;
    s.area = faces_area(g, p.faces[c]);
    s.proxy = p.fit[c].proxy;
    s.max_error_deg = p.fit[c].max_error * 180.0 / M_PI;
    s.rms_error_deg = p.fit[c].rms_error * 180.0 / M_PI;
    s.boundary_loops = topology[id].boundary_loops;
    s.euler = topology[id].euler();
    s.disk = topology[id].disk();
    s.kept = p.kept[c] != 0;
    s.source_patch = problem.patch.empty() ? -1 : problem.patch[p.faces[c].front()];
    s.over_limit = p.fit[c].max_error > limit ? p.over[c] : OverLimit::No;
    r.patches.push_back(s);
  }
  return r;
}

}  // namespace qd::segment
