// The Lloyd iteration of D-Charts and the final fill of the faces left free.
#include "segment/lloyd.h"

#include <algorithm>
#include <string>

#include "common/parallel_for.h"
#include "segment/chart_seeds.h"
#include "segment/common_names.h"
#include "segment/cone_fit.h"
#include "segment/partition.h"

namespace qd::segment {

namespace {

constexpr int kAdaptRounds = 8;      // refits of a new chart as it grows, at most
constexpr size_t kAdaptGrowth = 20;  // it stops when a refit adds less than 1/20 of its faces

// The cone fitted to `faces` with the chart's previous axis among the candidates. That axis with
// its midrange apex angle fits the faces at least as well as the previous cone, so faces that
// fit the previous cone within the limit fit the new one too.
ConeProxy refit(const FaceGeometry& g, const std::vector<int>& faces, const Vec3& axis,
                double limit) {
  return fit_cone(g, faces, limit, {axis}).proxy;
}

// A new chart at `seed`, a plane through its normal, grown into the free faces, then refitted
// to what it took and regrown from its seed while that makes it larger (D-Charts' proxy fitting
// applied to one chart as it grows, so a new chart on a cylinder becomes one cylinder).
void add_chart(const FaceGraph& graph, const FaceGeometry& g, const GrowSettings& s, int seed,
               LloydResult& r) {
  const int c = static_cast<int>(r.charts.size());
  r.charts.push_back({seed, plane_proxy(g.normal[seed]), g.area[seed]});
  std::vector<int> taken = grow_charts(graph, g, r.charts, r.label, s);
  for (int round = 0; round < kAdaptRounds; ++round) {
    const Chart previous = r.charts[c];
    r.charts[c].proxy = refit(g, taken, previous.proxy.axis, s.limit);
    r.charts[c].area_hint = faces_area(g, taken);
    for (const int f : taken) r.label[f] = kFree;
    std::vector<int> regrown = grow_charts(graph, g, r.charts, r.label, s);
    if (regrown.size() <= taken.size()) {  // no larger: keep what it had
      for (const int f : regrown) r.label[f] = kFree;
      for (const int f : taken) r.label[f] = c;
      r.charts[c] = previous;
      return;
    }
    const bool settled = regrown.size() * kAdaptGrowth < taken.size() * (kAdaptGrowth + 1);
    taken = std::move(regrown);
    if (settled) return;
  }
}

// D-Charts' re-seeding where no chart fits: new charts (add_chart) at the free faces, the most
// interior first (hops to the border of the free faces, counted once; ties to the lower index),
// each at a face still free when its turn comes, until no face is free.
void fill_free(const FaceGraph& graph, const FaceGeometry& g, const GrowSettings& s,
               LloydResult& r) {
  std::vector<int> free = faces_labelled(r.label, kFree);
  const std::vector<int> hops = hops_to_border(graph, r.label, free);
  std::sort(free.begin(), free.end(),
            [&](int a, int b) { return hops[a] != hops[b] ? hops[a] > hops[b] : a < b; });
  for (const int seed : free)
    if (r.label[seed] == kFree) add_chart(graph, g, s, seed, r);
}

// The proxy fitting and seed update of a Lloyd round.
void refit_and_reseed(const FaceGraph& graph, const FaceGeometry& g, const std::vector<int>& label,
                      const GrowSettings& s, int threads, std::vector<Chart>& charts) {
  const int count = static_cast<int>(charts.size());
  const std::vector<std::vector<int>> faces = faces_by_chart(label, count);
  parallel_for(charts.size(), static_cast<size_t>(threads), [&](size_t c) {
    charts[c].proxy = refit(g, faces[c], charts[c].proxy.axis, s.limit);
    charts[c].area_hint = faces_area(g, faces[c]);
  });
  std::vector<double> deviation(label.size(), 0.0);
  parallel_ranges(label.size(), static_cast<size_t>(threads), kRangeChunk,
                  [&](size_t begin, size_t end) {
                    for (size_t f = begin; f < end; ++f)
                      if (label[f] >= 0)
                        deviation[f] = cone_deviation(charts[label[f]].proxy, g.normal[f]);
                  });
  std::vector<int> in_charts;
  for (size_t f = 0; f < label.size(); ++f)
    if (label[f] >= 0) in_charts.push_back(static_cast<int>(f));
  const std::vector<int> hops = hops_to_border(graph, label, in_charts);
  const std::vector<int> fitting = interior_faces(hops, label, count, deviation, s.limit);
  for (int c = 0; c < count; ++c)
    if (fitting[c] >= 0) charts[c].seed = fitting[c];
}

}  // namespace

LloydResult lloyd_charts(const FaceGraph& graph, const FaceGeometry& g, std::vector<int> label,
                         const GrowSettings& settings, int max_rounds, int threads,
                         const Progress& progress, int percent_from, int percent_to) {
  LloydResult r;
  const std::vector<int> start = std::move(label);
  const auto active = static_cast<size_t>(std::count(start.begin(), start.end(), kFree));
  r.label = start;
  fill_free(graph, g, settings, r);
  if (progress)
    progress(percent_from,
             "Segmenting: first growth, " + std::to_string(r.charts.size()) + " charts");
  for (int round = 1; round <= max_rounds; ++round) {
    const std::vector<int> previous = r.label;
    const size_t charts = r.charts.size();
    refit_and_reseed(graph, g, r.label, settings, threads, r.charts);
    r.label = start;
    grow_charts(graph, g, r.charts, r.label, settings);
    fill_free(graph, g, settings, r);
    r.rounds = round;
    size_t changed = 0;
    for (size_t f = 0; f < start.size(); ++f) changed += r.label[f] != previous[f];
    if (progress)
      progress(percent_from + (percent_to - percent_from) * round / max_rounds,
               "Segmenting: round " + std::to_string(round) + ", " +
                   std::to_string(r.charts.size()) + " charts, " + std::to_string(changed) +
                   " faces changed chart");
    if (r.charts.size() == charts && changed * kSettled <= active) break;
  }
  return r;
}

}  // namespace qd::segment
