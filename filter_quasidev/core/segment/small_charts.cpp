// Growing charts below the smallest size by taking their neighbours' faces, best fitting first.
#include "segment/small_charts.h"

#include <algorithm>
#include <functional>
#include <queue>
#include <utility>

namespace qd::segment {

namespace {

constexpr size_t kDetour = 32;

class SmallChartGrower {
 public:
  SmallChartGrower(Partition& p, const FaceGraph& graph, const FaceGeometry& g,
                   const MinimumSize& size)
      : p_(p),
        graph_(graph),
        g_(g),
        size_(size),
        faces_(p.faces.size()),
        area_(p.faces.size()),
        touched_(p.faces.size(), 0) {
    for (size_t c = 0; c < p.faces.size(); ++c) {
      faces_[c] = static_cast<int>(p.faces[c].size());
      area_[c] = faces_area(g, p.faces[c]);
    }
  }

  bool small(int c) const { return faces_[c] < size_.faces || area_[c] < size_.area; }

  // Grows chart s until it has the smallest size or no neighbour can give a face; returns
  // whether it got there.
  bool grow(int s) {
    const ConeProxy cone = p_.fit[s].proxy;
    using Offer = std::pair<double, int>;  // (deviation from s's cone, face)
    std::priority_queue<Offer, std::vector<Offer>, std::greater<Offer>> heap;
    const auto offer_neighbours = [&](int f) {
      for (const int h : graph_.neighbour[f])
        if (h >= 0 && p_.label[h] >= 0 && p_.label[h] != s)
          heap.push({cone_deviation(cone, g_.normal[h]), h});
    };
    for (const int f : p_.faces[s]) offer_neighbours(f);
    while (small(s) && !heap.empty()) {
      const int f = heap.top().second;
      heap.pop();
      const int donor = p_.label[f];
      if (donor == s || !can_give(donor, f)) continue;
      p_.label[f] = s;
      --faces_[donor];
      area_[donor] -= g_.area[f];
      ++faces_[s];
      area_[s] += g_.area[f];
      touched_[donor] = touched_[s] = 1;
      offer_neighbours(f);
    }
    return !small(s);
  }

  const std::vector<char>& touched() const { return touched_; }

 private:
  // The donor stays at least the smallest size and edge-connected: its faces next to f still
  // reach each other without f within kDetour faces (around f's corner, as a rule).
  bool can_give(int donor, int f) const {
    if (faces_[donor] - 1 < size_.faces || area_[donor] - g_.area[f] < size_.area) return false;
    std::vector<int> next;
    for (const int h : graph_.neighbour[f])
      if (h >= 0 && p_.label[h] == donor) next.push_back(h);
    for (size_t k = 1; k < next.size(); ++k)
      if (!reaches(donor, f, next[0], next[k])) return false;
    return true;
  }

  // Whether a reaches b over the donor's faces other than f, visiting at most kDetour faces.
  bool reaches(int donor, int f, int a, int b) const {
    std::vector<int> seen = {f, a};
    for (size_t i = 1; i < seen.size() && seen.size() <= kDetour; ++i)
      for (const int h : graph_.neighbour[seen[i]]) {
        if (h == b) return true;
        if (h >= 0 && p_.label[h] == donor && std::find(seen.begin(), seen.end(), h) == seen.end())
          seen.push_back(h);
      }
    return false;
  }

  Partition& p_;
  const FaceGraph& graph_;
  const FaceGeometry& g_;
  const MinimumSize& size_;
  std::vector<int> faces_;
  std::vector<double> area_;
  std::vector<char> touched_;
};

}  // namespace

int grow_small_charts(Partition& p, const FaceGraph& graph, const FaceGeometry& g,
                      const MinimumSize& size, double limit) {
  SmallChartGrower grower(p, graph, g, size);
  std::vector<char> reached(p.faces.size(), 0);
  int count = 0;
  for (size_t c = 0; c < p.faces.size(); ++c) {
    const int s = static_cast<int>(c);
    if (p.faces[c].empty() || !grower.small(s)) continue;
    reached[c] = grower.grow(s);
    count += reached[c];
  }
  const std::vector<std::vector<int>> faces = faces_by_chart(p.label, int(p.faces.size()));
  for (size_t c = 0; c < p.faces.size(); ++c) {
    if (!grower.touched()[c]) continue;
    p.faces[c] = faces[c];
    const ConeFit refit = fit_cone(g, faces[c], limit);
    const ConeFit previous = measure_cone(g, faces[c], p.fit[c].proxy);
    p.fit[c] = better_fit(refit, previous, limit) ? refit : previous;
    if (reached[c] && p.fit[c].max_error > limit) p.over[c] = OverLimit::SmallestSize;
  }
  return count;
}

}  // namespace qd::segment
