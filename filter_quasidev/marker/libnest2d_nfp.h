// libnest2d's extension point for non-convex shapes: its Clipper backend's no-fit polygon
// handles only convex pairs (nfp::MaxNfpLevel defaults to CONVEX_ONLY), so the nested marker
// raises the level to BOTH_CONCAVE and computes the pairs with a concave shape by Clipper's
// Minkowski sum (minkowski_nfp.h). Include after <libnest2d/libnest2d.hpp>, before nesting.
#pragma once

#include <algorithm>
#include <libnest2d/libnest2d.hpp>

#include "minkowski_nfp.h"

namespace libnest2d {
namespace nfp {

template <>
struct MaxNfpLevel<PolygonImpl> {
  static const BP2D_CONSTEXPR NfpLevel value = NfpLevel::BOTH_CONCAVE;
};

// The no-fit polygon in place, with the point that the placer's correctNfpPosition moves to its
// own reference (the orbiter's top right vertex after its bottom left one is put on the
// stationary shape's top right one): the same point, so the correction is no move.
inline NfpResult<PolygonImpl> minkowski_nfp(const PolygonImpl& stationary,
                                            const PolygonImpl& orbiter) {
  const PointImpl reference = rightmostUpVertex(orbiter);
  ClipperLib::Path contour =
      qd::marker::no_fit_polygon(stationary.Contour, orbiter.Contour, reference);
  std::reverse(contour.begin(), contour.end());  // clockwise and closed, as libnest2d holds them
  if (!contour.empty()) contour.push_back(contour.front());
  const PointImpl touch = rightmostUpVertex(stationary) - leftmostDownVertex(orbiter);
  return {PolygonImpl(std::move(contour)), reference + touch};
}

struct MinkowskiNfp {
  NfpResult<PolygonImpl> operator()(const PolygonImpl& sh, const PolygonImpl& other) {
    return minkowski_nfp(sh, other);
  }
};

template <>
struct NfpImpl<PolygonImpl, NfpLevel::ONE_CONVEX> : MinkowskiNfp {};

template <>
struct NfpImpl<PolygonImpl, NfpLevel::BOTH_CONCAVE> : MinkowskiNfp {};

}  // namespace nfp
}  // namespace libnest2d
