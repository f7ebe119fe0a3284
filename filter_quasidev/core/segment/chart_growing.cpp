// Multi-source growing with one binary heap of (cost, face, chart) entries; an entry whose face
// has been taken meanwhile is skipped when it comes up.
#include "segment/chart_growing.h"

#include <functional>
#include <queue>
#include <tuple>

#include "segment/growing_cost.h"

namespace qd::segment {

namespace {

struct Entry {
  double cost;  // log of the growing cost
  int face, chart;
  bool operator>(const Entry& o) const {
    return std::tie(cost, face, chart) > std::tie(o.cost, o.face, o.chart);
  }
};

class Grower {
 public:
  Grower(const FaceGraph& graph, const FaceGeometry& g, const std::vector<Chart>& charts,
         std::vector<int>& label, const GrowSettings& s)
      : graph_(graph), g_(g), charts_(charts), label_(label), s_(s) {}

  std::vector<int> run() {
    for (size_t c = 0; c < charts_.size(); ++c)
      if (label_[charts_[c].seed] == kFree) take(charts_[c].seed, static_cast<int>(c));
    while (!heap_.empty()) {
      const Entry e = heap_.top();
      heap_.pop();
      if (label_[e.face] == kFree) take(e.face, e.chart);
    }
    return std::move(taken_);
  }

 private:
  void take(int f, int c) {
    label_[f] = c;
    taken_.push_back(f);
    for (const int h : graph_.neighbour[f])
      if (h >= 0 && label_[h] == kFree) offer(h, c);
  }

  // Queues face t for chart c if it may join it.
  void offer(int t, int c) {
    const Chart& chart = charts_[c];
    const double deviation = cone_deviation(chart.proxy, g_.normal[t]);
    if (deviation > s_.limit) return;
    double inner = 0, outer = 0;
    for (int k = 0; k < 3; ++k) {
      const int h = graph_.neighbour[t][k];
      (h >= 0 && label_[h] == c ? inner : outer) += graph_.side_length[t][k];
    }
    const double distance = (g_.centroid[t] - g_.centroid[chart.seed]).norm();
    heap_.push(
        {log_growing_cost(deviation, s_.limit, distance, chart.area_hint, outer, inner, s_.weights),
         t, c});
  }

  const FaceGraph& graph_;
  const FaceGeometry& g_;
  const std::vector<Chart>& charts_;
  std::vector<int>& label_;
  const GrowSettings& s_;
  std::vector<int> taken_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap_;
};

}  // namespace

std::vector<int> grow_charts(const FaceGraph& graph, const FaceGeometry& g,
                             const std::vector<Chart>& charts, std::vector<int>& label,
                             const GrowSettings& settings) {
  return Grower(graph, g, charts, label, settings).run();
}

}  // namespace qd::segment
