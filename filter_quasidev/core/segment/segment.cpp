// The segmentation pipeline: validation, regions kept whole, Lloyd iteration, merging, report.
#include "segment/segment.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/parallel_for.h"
#include "common/thread_count.h"
#include "segment/chart_merging.h"
#include "segment/common_names.h"
#include "segment/face_parts.h"
#include "segment/lloyd.h"
#include "segment/partition.h"
#include "segment/patch_report.h"
#include "segment/region_labels.h"
#include "segment/segment_log.h"
#include "segment/segment_validate.h"
#include "segment/small_charts.h"
#include "segment/split_charts.h"

namespace qd::segment {

namespace {

double radians(double degrees) { return degrees * M_PI / 180.0; }

// The parts of the input regions whose faces fit one cone within the limit: one chart each.
// Their faces are marked kOutside in `label` so the Lloyd iteration leaves them alone.
Partition regions_kept_whole(const FaceGraph& graph, const FaceGeometry& g,
                             const std::vector<int>& region, double limit, int threads,
                             std::vector<int>& label) {
  const FaceParts parts =
      connected_parts(graph, region.empty() ? std::vector<int>(label.size(), 0) : region);
  const std::vector<std::vector<int>> faces = faces_by_chart(parts.part, parts.count);
  std::vector<ConeFit> fits(faces.size());
  parallel_for(faces.size(), static_cast<size_t>(threads),
               [&](size_t p) { fits[p] = fit_cone(g, faces[p], limit); });
  Partition kept;
  for (size_t p = 0; p < faces.size(); ++p) {
    if (fits[p].max_error > limit) continue;
    for (const int f : faces[p]) label[f] = kOutside;
    kept.faces.push_back(faces[p]);
    kept.fit.push_back(fits[p]);
  }
  return kept;
}

// The Lloyd charts followed by the regions kept whole, with their fits: each chart's cone is
// the better of its refit and the proxy it grew with (which all its faces fit).
Partition charts_and_kept(const LloydResult& lloyd, Partition kept, const FaceGeometry& g,
                          double limit, int threads) {
  Partition p;
  const auto m = static_cast<int>(lloyd.charts.size());
  p.label = lloyd.label;
  p.faces = faces_by_chart(p.label, m);
  p.fit.resize(p.faces.size());
  parallel_for(p.faces.size(), static_cast<size_t>(threads), [&](size_t c) {
    const ConeFit refit = fit_cone(g, p.faces[c], limit);
    const ConeFit grown = measure_cone(g, p.faces[c], lloyd.charts[c].proxy);
    p.fit[c] = better_fit(refit, grown, limit) ? refit : grown;
  });
  p.over.assign(p.faces.size(), OverLimit::No);
  p.kept.assign(p.faces.size(), 0);
  for (size_t k = 0; k < kept.faces.size(); ++k) {
    for (const int f : kept.faces[k]) p.label[f] = m + static_cast<int>(k);
    p.faces.push_back(std::move(kept.faces[k]));
    p.fit.push_back(kept.fit[k]);
    p.over.push_back(OverLimit::No);
    p.kept.push_back(1);
  }
  return p;
}

// D-Charts' merging, then the charts below the smallest size, then the target count.
void merge_all(Partition& p, const FaceGraph& graph, const FaceGeometry& g,
               const GrowSettings& grow, const SegmentParams& q, int threads) {
  MergeSettings s;
  s.limit = grow.limit;
  s.min_faces = q.min_faces;
  s.min_area = q.min_area * g.total_area;
  s.target = q.target_patches;
  s.threads = threads;
  merge_charts(p, graph, g, MergeRule::WithinLimit, s);
  grow_small_charts(p, graph, g, {s.min_faces, s.min_area}, s.limit);
  merge_charts(p, graph, g, MergeRule::SmallCharts, s);
  if (q.target_patches == 0) return;
  merge_charts(p, graph, g, MergeRule::TargetCount, s);
  split_charts(p, graph, g, grow, {s.min_faces, s.min_area}, q.target_patches);
}

}  // namespace

SegmentResult segment(const SegmentProblem& problem, const Progress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  validate_segment(problem);
  const SegmentParams& q = problem.params;
  const int threads = static_cast<int>(thread_count(q.threads));
  const double limit = radians(q.max_error_deg);
  if (progress) progress(0, "Segmenting: face normals and adjacency");

  const FaceGeometry g = face_geometry(problem.V, problem.F, threads);
  const std::vector<int> region = region_labels(problem.patch, problem.selected);
  FaceGraph graph = face_graph(problem.V, problem.F, region);
  std::vector<int> label(static_cast<size_t>(problem.F.rows()), kFree);
  Partition kept = regions_kept_whole(graph, g, region, limit, threads, label);
  remove_creases(graph, g, radians(q.crease_deg));

  GrowSettings s;
  s.limit = limit;
  s.weights = q.weights;
  const LloydResult lloyd =
      lloyd_charts(graph, g, std::move(label), s, q.max_rounds, threads, progress, 5, 85);
  Partition p = charts_and_kept(lloyd, std::move(kept), g, limit, threads);
  if (progress) progress(90, "Segmenting: merging charts");
  merge_all(p, graph, g, s, q, threads);

  SegmentResult r = patch_report(p, problem, g);
  r.rounds = lloyd.rounds;
  r.warnings = segment_warnings(graph.nonmanifold_edges, graph.misoriented_edges, r, q);
  r.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  r.log = segment_log(r, static_cast<int>(problem.F.rows()), q);
  if (progress) progress(100, "Segmenting: done");
  return r;
}

}  // namespace qd::segment
