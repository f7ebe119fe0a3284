// Two-chart growing inside one chart, and the choice of the chart to cut.
#include "segment/split_charts.h"

#include <array>
#include <cmath>
#include <tuple>

#include "segment/chart_seeds.h"

namespace qd::segment {

namespace {

class Splitter {
 public:
  Splitter(Partition& p, const FaceGraph& graph, const FaceGeometry& g, const GrowSettings& s,
           const MinimumSize& size)
      : p_(p), graph_(graph), g_(g), s_(s), size_(size) {}

  // Cuts chart c in two; false if a half would be below the smallest size or not every face
  // was reached.
  bool split(int c) {
    const std::vector<int>& faces = p_.faces[c];
    std::vector<int> label(p_.label.size(), kOutside);
    for (const int f : faces) label[f] = kFree;
    std::array<int, 2> seed = {interior(p_.label, c, faces, -1), worst(faces, p_.fit[c].proxy)};
    if (seed[0] == seed[1]) seed[0] = interior(p_.label, c, faces, seed[1]);
    std::vector<Chart> halves = {
        {seed[0], p_.fit[c].proxy, faces_area(g_, faces) / 2},
        {seed[1], plane_proxy(g_.normal[seed[1]]), faces_area(g_, faces) / 2}};
    GrowSettings all = s_;
    all.limit = M_PI;  // every face is admitted; the fit term still orders them
    for (int round = 0;; ++round) {
      for (const int f : faces) label[f] = kFree;
      grow_charts(graph_, g_, halves, label, all);
      if (round == kSplitRounds) break;
      const std::vector<std::vector<int>> parts = faces_by_chart(label, 2);
      for (int h = 0; h < 2; ++h) {
        if (parts[h].empty()) return false;
        halves[h].proxy = fit_cone(g_, parts[h], s_.limit, {halves[h].proxy.axis}).proxy;
        halves[h].area_hint = faces_area(g_, parts[h]);
        halves[h].seed = interior(label, h, parts[h], -1);
      }
    }
    const std::vector<std::vector<int>> parts = faces_by_chart(label, 2);
    for (const std::vector<int>& part : parts)
      if (static_cast<int>(part.size()) < size_.faces || faces_area(g_, part) < size_.area)
        return false;
    if (parts[0].size() + parts[1].size() != faces.size()) return false;
    const int added = static_cast<int>(p_.faces.size());
    for (const int f : parts[1]) p_.label[f] = added;
    p_.faces[c] = parts[0];
    p_.faces.push_back(parts[1]);
    p_.over.push_back(p_.over[c]);
    p_.kept[c] = 0;
    p_.kept.push_back(0);
    p_.fit.push_back(p_.fit[c]);
    for (const int h : {c, added}) {  // the whole's axis fits each half at least as well
      p_.fit[h] = fit_cone(g_, p_.faces[h], s_.limit, {p_.fit[h].proxy.axis});
      if (p_.fit[h].max_error <= s_.limit) p_.over[h] = OverLimit::No;
    }
    return true;
  }

 private:
  // The face of `faces` (labelled `l`) with the most hops to their border, other than `not_this`;
  // ties to the lower index.
  int interior(const std::vector<int>& label, int l, const std::vector<int>& faces,
               int not_this) const {
    const std::vector<int> hops = hops_to_border(graph_, label, faces);
    int best = -1;
    for (const int f : faces)
      if (f != not_this && label[f] == l && (best < 0 || hops[f] > hops[best])) best = f;
    return best;
  }

  // The face of `faces` that deviates most from the cone; ties to the lower index.
  int worst(const std::vector<int>& faces, const ConeProxy& cone) const {
    int best = faces.front();
    for (const int f : faces)
      if (cone_deviation(cone, g_.normal[f]) > cone_deviation(cone, g_.normal[best])) best = f;
    return best;
  }

  Partition& p_;
  const FaceGraph& graph_;
  const FaceGeometry& g_;
  const GrowSettings& s_;
  const MinimumSize& size_;
};

}  // namespace

int split_charts(Partition& p, const FaceGraph& graph, const FaceGeometry& g, const GrowSettings& s,
                 const MinimumSize& size, int target) {
  Splitter splitter(p, graph, g, s, size);
  std::vector<char> tried(p.faces.size(), 0);
  int alive = 0;
  for (const std::vector<int>& faces : p.faces) alive += !faces.empty();
  int added = 0;
  while (alive + added < target) {
    int pick = -1;
    double pick_area = 0;
    for (size_t c = 0; c < p.faces.size(); ++c) {
      if (p.faces[c].size() < 2 * static_cast<size_t>(size.faces) || (c < tried.size() && tried[c]))
        continue;
      const double area = faces_area(g, p.faces[c]);
      if (area < 2 * size.area) continue;
      if (pick < 0 || std::make_tuple(p.fit[c].rms_error * area, area) >
                          std::make_tuple(p.fit[pick].rms_error * pick_area, pick_area)) {
        pick = static_cast<int>(c);
        pick_area = area;
      }
    }
    if (pick < 0) break;
    if (splitter.split(pick)) {
      ++added;
      tried.assign(p.faces.size(), 0);
    } else {
      tried[pick] = 1;
    }
  }
  return added;
}

}  // namespace qd::segment
