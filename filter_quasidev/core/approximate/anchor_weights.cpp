#include "approximate/anchor_weights.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <nanoflann.hpp>

#include "approximate/common_names.h"
#include "common/parallel_for.h"

namespace qd::approximate {
namespace {

// nanoflann view of the constrained vertices.
struct ConstrainedCloud {
  const Positions& V;
  std::vector<int> ids;
  size_t kdtree_get_point_count() const { return ids.size(); }
  double kdtree_get_pt(size_t i, size_t dim) const {
    return V(ids[i], static_cast<Eigen::Index>(dim));
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using Tree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, ConstrainedCloud>,
                                        ConstrainedCloud, 3, uint32_t>;

}  // namespace

std::vector<double> mls_weights(const Positions& V, const std::vector<char>& fixed, double ae,
                                int threads) {
  constexpr double kEpsilon = 0.001;  // ε of Eq. (15)
  assert(static_cast<size_t>(V.rows()) == fixed.size());
  assert(ae > 0);  // validation refuses zero-area faces: the weights are finite and positive
  std::vector<double> w(fixed.size(), 0.0);
  ConstrainedCloud cloud{V, {}};
  for (size_t v = 0; v < fixed.size(); ++v)
    if (fixed[v]) cloud.ids.push_back(static_cast<int>(v));
  if (cloud.ids.empty()) return w;
  Tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  parallel_ranges(fixed.size(), static_cast<size_t>(std::max(threads, 1)), kRangeChunk,
                  [&](size_t first, size_t last) {
                    for (size_t v = first; v < last; ++v) {
                      const Vec3 p = V.row(static_cast<Eigen::Index>(v)).transpose();
                      uint32_t nearest = 0;
                      double d2 = 0;
                      tree.knnSearch(p.data(), 1, &nearest, &d2);
                      w[v] = 1.0 / (std::sqrt(d2) / ae + kEpsilon * kEpsilon);  // Eq. (15)
                    }
                  });
  return w;
}

}  // namespace qd::approximate
