#include "minkowski_nfp.h"

#include <cmath>

namespace qd::marker {

namespace {

// The polygon without its repeated closing point.
ClipperLib::Path open(const ClipperLib::Path& path) {
  ClipperLib::Path p = path;
  if (p.size() > 1 && p.front() == p.back()) p.pop_back();
  return p;
}

}  // namespace

ClipperLib::Path no_fit_polygon(const ClipperLib::Path& stationary, const ClipperLib::Path& orbiter,
                                const ClipperLib::IntPoint& reference) {
  // Where the reference is when the orbiter's point b sits at the origin.
  ClipperLib::Path turned;
  for (const ClipperLib::IntPoint& b : open(orbiter))
    turned.emplace_back(reference.X - b.X, reference.Y - b.Y);
  // The sum of the two boundaries: its outer contour is the sum's outer contour.
  ClipperLib::Paths sum;
  ClipperLib::MinkowskiSum(turned, open(stationary), sum, true);
  ClipperLib::Path outer;
  double largest = 0;
  for (ClipperLib::Path& p : sum) {
    const double area = ClipperLib::Area(p);
    if (area > largest) {
      largest = area;
      outer = std::move(p);
    }
  }
  return outer;
}

}  // namespace qd::marker
