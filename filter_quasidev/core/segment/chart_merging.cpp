// Greedy pairwise merging with a heap of candidate pairs; a candidate whose charts have changed
// since it was fitted is dropped when it comes up.
#include "segment/chart_merging.h"

#include <algorithm>
#include <functional>
#include <iterator>
#include <optional>
#include <queue>
#include <set>
#include <tuple>
#include <utility>

#include "common/parallel_for.h"
#include "segment/common_names.h"

namespace qd::segment {

namespace {

constexpr size_t kParallelFaces = 20000;  // fewer faces to fit are not worth starting threads

// A pair and the cone of its union, ordered as better_fit() orders cones: within the limit by
// the largest error, then over it by the root mean square, then by the charts' indices.
struct Candidate {
  bool over;     // the union's largest error is over the limit
  double error;  // its largest error if not, else its root mean square, radians
  int a, b;      // a < b
  int version_a, version_b;
  ConeFit fit;
  bool operator>(const Candidate& o) const {
    return std::tie(over, error, a, b) > std::tie(o.over, o.error, o.a, o.b);
  }
};

class Merger {
 public:
  Merger(Partition& p, const FaceGraph& graph, const FaceGeometry& g, MergeRule rule,
         const MergeSettings& s)
      : p_(p),
        g_(g),
        rule_(rule),
        s_(s),
        neighbours_(p.faces.size()),
        version_(p.faces.size(), 0),
        moments_(p.faces.size()),
        area_(p.faces.size()) {
    for (size_t c = 0; c < p.faces.size(); ++c) {
      moments_[c] = normal_moments(g, p.faces[c]);
      area_[c] = moments_[c].area;
      alive_ += !p.faces[c].empty();
    }
    for (size_t f = 0; f < p.label.size(); ++f)
      for (const int h : graph.neighbour[f])
        if (h >= 0) adjacent(p.label[f], p.label[h]);
    if (rule == MergeRule::TargetCount)
      for (const auto& [f, h] : graph.creases) {
        adjacent(p.label[f], p.label[h]);
        adjacent(p.label[h], p.label[f]);
      }
  }

  int run() {
    std::vector<std::pair<int, int>> pairs;
    for (size_t a = 0; a < neighbours_.size(); ++a)
      for (const int b : neighbours_[a])
        if (static_cast<int>(a) < b) pairs.emplace_back(static_cast<int>(a), b);
    offer(pairs);
    int merges = 0;
    while (!heap_.empty() && !done()) {
      const Candidate c = heap_.top();
      heap_.pop();
      if (c.version_a != version_[c.a] || c.version_b != version_[c.b] || !eligible(c.a, c.b))
        continue;
      merge(c);
      ++merges;
    }
    return merges;
  }

 private:
  void adjacent(int a, int b) {
    if (a >= 0 && b >= 0 && a != b) neighbours_[a].insert(b);
  }

  bool small(int c) const {
    return static_cast<int>(p_.faces[c].size()) < s_.min_faces || area_[c] < s_.min_area;
  }
  bool eligible(int a, int b) const {
    return rule_ != MergeRule::SmallCharts || small(a) || small(b);
  }
  bool done() const { return rule_ == MergeRule::TargetCount && alive_ <= s_.target; }

  // The union's cone, with either chart's axis among the candidates.
  std::optional<ConeFit> fit_union(int a, int b) const {
    if (rule_ == MergeRule::WithinLimit) {
      NormalMoments m = moments_[a];
      m += moments_[b];
      if (max_error_lower_bound(m) > s_.limit) return std::nullopt;
    }
    std::vector<int> faces;
    faces.reserve(p_.faces[a].size() + p_.faces[b].size());
    std::merge(p_.faces[a].begin(), p_.faces[a].end(), p_.faces[b].begin(), p_.faces[b].end(),
               std::back_inserter(faces));
    const ConeFit best =
        fit_cone(g_, faces, s_.limit, {p_.fit[a].proxy.axis, p_.fit[b].proxy.axis});
    if (rule_ == MergeRule::WithinLimit && best.max_error > s_.limit) return std::nullopt;
    return best;
  }

  // Fits the eligible pairs, in parallel when they hold many faces, and queues those that may
  // merge, in order.
  void offer(const std::vector<std::pair<int, int>>& pairs) {
    size_t work = 0;
    for (const auto& [a, b] : pairs) work += p_.faces[a].size() + p_.faces[b].size();
    const size_t threads = work > kParallelFaces ? static_cast<size_t>(s_.threads) : 1;
    std::vector<std::optional<ConeFit>> fits(pairs.size());
    parallel_for(pairs.size(), threads, [&](size_t i) {
      if (eligible(pairs[i].first, pairs[i].second))
        fits[i] = fit_union(pairs[i].first, pairs[i].second);
    });
    for (size_t i = 0; i < pairs.size(); ++i) {
      if (!fits[i]) continue;
      const auto [a, b] = pairs[i];
      const bool over = fits[i]->max_error > s_.limit;
      heap_.push({over, over ? fits[i]->rms_error : fits[i]->max_error, a, b, version_[a],
                  version_[b], *fits[i]});
    }
  }

  void merge(const Candidate& c) {
    const int keep = c.a, gone = c.b;
    const bool both_small = small(keep) && small(gone);
    std::vector<int> faces;
    faces.reserve(p_.faces[keep].size() + p_.faces[gone].size());
    std::merge(p_.faces[keep].begin(), p_.faces[keep].end(), p_.faces[gone].begin(),
               p_.faces[gone].end(), std::back_inserter(faces));
    for (const int f : p_.faces[gone]) p_.label[f] = keep;
    p_.faces[keep] = std::move(faces);
    p_.faces[gone].clear();
    p_.fit[keep] = c.fit;
    p_.over[keep] = c.fit.max_error <= s_.limit       ? OverLimit::No
                    : rule_ == MergeRule::TargetCount ? OverLimit::TargetCount
                    : both_small                      ? OverLimit::SmallestSize
                                                      : OverLimit::SmallPart;
    moments_[keep] += moments_[gone];
    area_[keep] += area_[gone];
    for (const int n : neighbours_[gone]) {
      neighbours_[n].erase(gone);
      if (n != keep) {
        neighbours_[n].insert(keep);
        neighbours_[keep].insert(n);
      }
    }
    neighbours_[gone].clear();
    neighbours_[keep].erase(gone);
    ++version_[keep];
    ++version_[gone];
    --alive_;
    std::vector<std::pair<int, int>> pairs;
    for (const int n : neighbours_[keep]) pairs.emplace_back(std::min(keep, n), std::max(keep, n));
    offer(pairs);
  }

  Partition& p_;
  const FaceGeometry& g_;
  const MergeRule rule_;
  const MergeSettings& s_;
  std::vector<std::set<int>> neighbours_;
  std::vector<int> version_;
  std::vector<NormalMoments> moments_;
  std::vector<double> area_;
  int alive_ = 0;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> heap_;
};

}  // namespace

int merge_charts(Partition& p, const FaceGraph& graph, const FaceGeometry& g, MergeRule rule,
                 const MergeSettings& s) {
  return Merger(p, graph, g, rule, s).run();
}

}  // namespace qd::segment
