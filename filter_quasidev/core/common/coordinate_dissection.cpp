#include "common/coordinate_dissection.h"

#include <algorithm>
#include <numeric>

namespace qd::common {
namespace {

struct Dissection {
  Dissection(const BlockPattern& graph, const std::vector<Vec3>& at, int most)
      : start(static_cast<size_t>(graph.blocks()) + 1, 0),
        points(at),
        leaf(std::max(most, 1)),
        part(static_cast<size_t>(graph.blocks()), 0),
        set(static_cast<size_t>(graph.blocks()), 0) {
    for (int c = 0; c < graph.blocks(); ++c)
      for (int s = graph.begin(c); s < graph.end(c); ++s) {
        ++start[static_cast<size_t>(c) + 1];
        ++start[static_cast<size_t>(graph.row(s)) + 1];
      }
    std::partial_sum(start.begin(), start.end(), start.begin());
    neighbour.resize(static_cast<size_t>(start.back()));
    std::vector<int> next(start.begin(), start.end() - 1);
    for (int c = 0; c < graph.blocks(); ++c)
      for (int s = graph.begin(c); s < graph.end(c); ++s) {
        const int r = graph.row(s);
        neighbour[static_cast<size_t>(next[static_cast<size_t>(c)]++)] = r;
        neighbour[static_cast<size_t>(next[static_cast<size_t>(r)]++)] = c;
      }
  }

  std::vector<int> start, neighbour;  // symmetric adjacency (CSR)
  const std::vector<Vec3>& points;
  int leaf;
  std::vector<int> part;  // the part each node is in while it is cut (-1: a separator's)
  std::vector<int> set;
  int parts = 1, sets = 0;

  bool touches(int v, int other) const {
    for (int k = start[static_cast<size_t>(v)]; k < start[static_cast<size_t>(v) + 1]; ++k)
      if (part[static_cast<size_t>(neighbour[static_cast<size_t>(k)])] == other) return true;
    return false;
  }

  // Nodes [b, mid) of `order` those of [b, e) below the median along `axis`, in part `low`; the
  // others in part `high`.
  void split(std::vector<int>& order, size_t b, size_t mid, size_t e, int axis, int low, int high) {
    std::nth_element(order.begin() + static_cast<long>(b), order.begin() + static_cast<long>(mid),
                     order.begin() + static_cast<long>(e), [&](int u, int v) {
                       const double pu = points[static_cast<size_t>(u)][axis];
                       const double pv = points[static_cast<size_t>(v)][axis];
                       return pu < pv || (pu == pv && u < v);
                     });
    for (size_t i = b; i < mid; ++i) part[static_cast<size_t>(order[i])] = low;
    for (size_t i = mid; i < e; ++i) part[static_cast<size_t>(order[i])] = high;
  }

  // How many nodes of each part touch the other.
  std::pair<size_t, size_t> touching(const std::vector<int>& order, size_t b, size_t mid, size_t e,
                                     int low, int high) const {
    size_t l = 0, h = 0;
    for (size_t i = b; i < mid; ++i) l += touches(order[i], high);
    for (size_t i = mid; i < e; ++i) h += touches(order[i], low);
    return {l, h};
  }

  // Cuts nodes [b, e) of `order` (one part) and numbers their sets.
  void cut(std::vector<int>& order, size_t b, size_t e) {
    if (e - b <= static_cast<size_t>(leaf)) {
      const int s = sets++;
      for (size_t i = b; i < e; ++i) set[static_cast<size_t>(order[i])] = s;
      return;
    }
    // Cut along x, y and z in turn, and made along the axis whose separator has fewest nodes:
    // those of one half that touch the other, in the half where they are fewer.
    const size_t mid = b + (e - b) / 2;
    const int low = parts++, high = parts++;
    int best_axis = 0;
    size_t best = 0;
    bool from_low = false;
    for (int axis = 0; axis < 3; ++axis) {
      split(order, b, mid, e, axis, low, high);
      const auto [l, h] = touching(order, b, mid, e, low, high);
      if (axis == 0 || std::min(l, h) < best) {
        best_axis = axis;
        best = std::min(l, h);
        from_low = l < h;
      }
    }
    if (best_axis != 2) split(order, b, mid, e, best_axis, low, high);
    // The separator goes to the end of its half, where the halves' own cuts leave it.
    const size_t sb = from_low ? b : mid, se = from_low ? mid : e;
    const int other = from_low ? high : low;
    const size_t kept =
        static_cast<size_t>(std::stable_partition(order.begin() + static_cast<long>(sb),
                                                  order.begin() + static_cast<long>(se),
                                                  [&](int v) { return !touches(v, other); }) -
                            order.begin());
    for (size_t i = kept; i < se; ++i) part[static_cast<size_t>(order[i])] = -1;
    cut(order, b, from_low ? kept : mid);
    cut(order, mid, from_low ? e : kept);
    const int s = sets++;
    for (size_t i = kept; i < se; ++i) set[static_cast<size_t>(order[i])] = s;
  }
};

}  // namespace

std::vector<int> coordinate_dissection(const BlockPattern& graph, const std::vector<Vec3>& points,
                                       int leaf) {
  Dissection d(graph, points, leaf);
  std::vector<int> order(static_cast<size_t>(graph.blocks()));
  std::iota(order.begin(), order.end(), 0);
  d.cut(order, 0, order.size());
  return d.set;
}

}  // namespace qd::common
