// The exact no-fit polygon of two simple polygons, convex or not, from Clipper's Minkowski sum
// (Angus Johnson's Clipper 6.4.2, MinkowskiSum): where a moving polygon's reference point can
// be without the polygon overlapping a fixed one. Used by the nested marker through libnest2d
// (see libnest2d_nfp.h), whose own no-fit polygon is exact only for convex shapes.
#pragma once

#include <polyclipping/clipper.hpp>

namespace qd::marker {

// stationary, orbiter: simple polygons in Clipper's integer coordinates, either orientation, a
// repeated closing point allowed. The orbiter's point `reference` (in the orbiter's current
// coordinates) touches or enters the stationary polygon exactly on and inside the returned
// polygon: the outer contour of stationary ⊕ (reference − orbiter), counter-clockwise
// (positive Clipper area), not closed. Its holes (positions enclosed by the stationary polygon
// where the orbiter would fit) are left out: they are filled, which is conservative.
ClipperLib::Path no_fit_polygon(const ClipperLib::Path& stationary, const ClipperLib::Path& orbiter,
                                const ClipperLib::IntPoint& reference);

}  // namespace qd::marker
