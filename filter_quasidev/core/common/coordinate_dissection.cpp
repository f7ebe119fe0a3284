#include "common/coordinate_dissection.h"

#include <algorithm>
#include <numeric>

namespace qd::common {
namespace {

struct Dissection {
  std::vector<int> start, neighbour;  // symmetric adjacency (CSR)
  const std::vector<Vec3>& points;
  int leaf;
  std::vector<int> part;  // the part each node is in while it is cut
  std::vector<int> set;
  int parts = 0, sets = 0;

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
    // The cut along each axis in turn; the one whose separator has fewest nodes is made.
    const size_t mid = b + (e - b) / 2;
    const int low = parts++, high = parts++;
    size_t low_touching = 0, high_touching = 0;
    int best_axis = -1;
    size_t best = 0;
    for (int axis = 0; axis < 3; ++axis) {
      split(order, b, mid, e, axis, low, high);
      const auto [l, h] = touching(order, b, mid, e, low, high);
      if (best_axis < 0 || std::min(l, h) < best) {
        best_axis = axis;
        best = std::min(l, h);
        low_touching = l;
        high_touching = h;
      }
    }
    if (best_axis != 2) split(order, b, mid, e, best_axis, low, high);
    const bool from_low = low_touching < high_touching;
    std::vector<int> separator;
    separator.reserve(from_low ? low_touching : high_touching);
    const size_t sb = from_low ? b : mid, se = from_low ? mid : e;
    const int other = from_low ? high : low;
    const auto kept = std::stable_partition(order.begin() + static_cast<long>(sb),
                                            order.begin() + static_cast<long>(se),
                                            [&](int v) { return !touches(v, other); });
    separator.assign(kept, order.begin() + static_cast<long>(se));
    const size_t kept_end = static_cast<size_t>(kept - order.begin());
    for (int v : separator) part[static_cast<size_t>(v)] = -1;
    if (from_low) {
      cut(order, b, kept_end);
      cut(order, mid, e);
    } else {
      cut(order, b, mid);
      cut(order, mid, kept_end);
    }
    const int s = sets++;
    for (int v : separator) set[static_cast<size_t>(v)] = s;
  }
};

}  // namespace

std::vector<int> coordinate_dissection(const BlockPattern& graph, const std::vector<Vec3>& points,
                                       int leaf) {
  const int n = graph.blocks();
  Dissection d{{},
               {},
               points,
               std::max(leaf, 1),
               std::vector<int>(static_cast<size_t>(n), 0),
               std::vector<int>(static_cast<size_t>(n), 0)};
  d.start.assign(static_cast<size_t>(n) + 1, 0);
  for (int c = 0; c < n; ++c)
    for (int s = graph.begin(c); s < graph.end(c); ++s) {
      ++d.start[static_cast<size_t>(c) + 1];
      ++d.start[static_cast<size_t>(graph.row(s)) + 1];
    }
  std::partial_sum(d.start.begin(), d.start.end(), d.start.begin());
  d.neighbour.resize(static_cast<size_t>(d.start.back()));
  std::vector<int> fill(d.start.begin(), d.start.end() - 1);
  for (int c = 0; c < n; ++c)
    for (int s = graph.begin(c); s < graph.end(c); ++s) {
      const int r = graph.row(s);
      d.neighbour[static_cast<size_t>(fill[static_cast<size_t>(c)]++)] = r;
      d.neighbour[static_cast<size_t>(fill[static_cast<size_t>(r)]++)] = c;
    }
  std::vector<int> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  d.parts = 1;
  d.cut(order, 0, order.size());
  return d.set;
}

}  // namespace qd::common
