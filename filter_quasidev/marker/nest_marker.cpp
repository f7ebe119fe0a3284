#include "nest_marker.h"

#include <algorithm>
#include <boost/geometry.hpp>
#include <cmath>
#include <limits>
#include <memory>

#include "libnest2d_nfp.h"
#include "marker_items.h"

namespace qd::marker {

namespace {

namespace ln = libnest2d;

constexpr double kCoordinates = 1e7;  // integer units across the fabric's width
constexpr double kTolerance = 3e-4;   // how far the nested shapes hold off the cut lines, by width

using Ring = boost::geometry::model::ring<boost::geometry::model::d2::point_xy<double>>;

// The shape libnest2d nests for a placement, in its integer coordinates (clockwise, closed, as
// it wants them): the cut line pushed out by `tolerance` (Clipper's offset), then simplified
// within half of it (Douglas-Peucker, Boost.Geometry), so it holds the cut line with a few
// vertices. Fewer vertices keep the no-fit polygons (their product) and the search along them
// fast.
ln::Item nesting_item(const MarkerPlacement& p, double scale, double tolerance) {
  ClipperLib::Path cut;
  for (const Eigen::Vector2d& q : p.outline)
    cut.emplace_back(std::llround(q.x() * scale), std::llround(q.y() * scale));
  ClipperLib::ClipperOffset offset;
  offset.AddPath(cut, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  ClipperLib::Paths pushed;
  offset.Execute(pushed, tolerance * scale);
  Ring ring, simple;
  for (const ClipperLib::Path& path : pushed)
    if (ClipperLib::Area(path) > 0) {  // the outer loop, counter-clockwise
      for (auto q = path.rbegin(); q != path.rend(); ++q)
        ring.emplace_back(static_cast<double>(q->X), static_cast<double>(q->Y));
      ring.push_back(ring.front());
    }
  boost::geometry::simplify(ring, simple, 0.5 * tolerance * scale);
  ClipperLib::Path path;
  for (const auto& q : simple) path.emplace_back(std::llround(q.x()), std::llround(q.y()));
  return ln::Item(std::move(path));
}

// The placer's score of a candidate position: the marker's length with the item there, then
// how far left the item is, plus a penalty for leaving the strip's width.
ln::NfpPlacer::Config placer_config(const ln::Box& bin) {
  ln::NfpPlacer::Config config;
  config.rotations = {0.0, ln::Pi};  // only these keep the grain along the length
  config.accuracy = 1.0f;            // start the search at every vertex of the no-fit polygons
  config.alignment = ln::NfpPlacer::Config::Alignment::BOTTOM_LEFT;
  config.starting_point = ln::NfpPlacer::Config::Alignment::BOTTOM_LEFT;
  auto pile = std::make_shared<ln::Box>(bin.minCorner(), bin.minCorner());
  config.before_packing = [pile](const ln::nfp::Shapes<ClipperLib::Polygon>& merged, const auto&,
                                 const auto&) {
    *pile = merged.empty() ? ln::Box(ln::Point(0, 0), ln::Point(0, 0))
                           : ln::shapelike::boundingBox(merged);
  };
  const double length = static_cast<double>(bin.width()), width = static_cast<double>(bin.height());
  config.object_function = [pile, bin, length, width](const ln::Item& item) {
    const ln::Box box = item.boundingBox();
    const double right =
        static_cast<double>(std::max(ln::getX(pile->maxCorner()), ln::getX(box.maxCorner())));
    const double left = static_cast<double>(ln::getX(box.minCorner()));
    const ln::Point below = bin.minCorner() - box.minCorner(),
                    above = box.maxCorner() - bin.maxCorner();
    const double out = static_cast<double>(std::max<ln::Coord>(0, ln::getX(below)) +
                                           std::max<ln::Coord>(0, ln::getY(below)) +
                                           std::max<ln::Coord>(0, ln::getY(above)));
    return right / length + 0.25 * left / length + 10 * out / width;
  };
  return config;
}

}  // namespace

Marker nest_marker(const flatten::Pattern& pattern, double width, double gap) {
  Marker marker;
  marker.width = width;
  std::vector<MarkerPlacement> placements = marker_items(pattern);
  const double scale = kCoordinates / width;
  double length = gap;
  std::vector<ln::Item> items;
  for (const MarkerPlacement& p : placements) {
    items.push_back(nesting_item(p, scale, kTolerance * width));
    length += static_cast<double>(items.back().boundingBox().width()) / scale + gap;
  }
  const ln::Box bin(ln::Point(0, 0),
                    ln::Point(std::llround(length * scale), std::llround(kCoordinates)));
  ln::nest(items, bin, std::llround(gap * scale), ln::NestConfig<>(placer_config(bin)));

  // The bins in order, each after the previous one's pieces (one bin, unless libnest2d gives up
  // on a piece in the first one).
  int bins = 0;
  for (const ln::Item& item : items) bins = std::max(bins, item.binId() + 1);
  double start = 0;
  for (int b = 0; b < bins; ++b) {
    const size_t first = marker.placements.size();
    double left = std::numeric_limits<double>::max(), right = start;
    for (size_t i = 0; i < items.size(); ++i) {
      if (items[i].binId() != b) continue;
      MarkerPlacement p = placements[i];
      const ln::Radians angle = items[i].rotation();
      const Eigen::Rotation2Dd turn(std::atan2(angle.sin(), angle.cos()));
      const ln::Point t = items[i].translation();
      p.rotation += turn.angle();
      for (Eigen::Vector2d& q : p.outline) {
        q = turn * q;
        left = std::min(left, q.x() + static_cast<double>(ln::getX(t)) / scale);
      }
      translate_placement(
          p, Eigen::Vector2d(static_cast<double>(ln::getX(t)), static_cast<double>(ln::getY(t))) /
                 scale);
      marker.placements.push_back(std::move(p));
    }
    for (size_t i = first; i < marker.placements.size(); ++i) {
      translate_placement(marker.placements[i], Eigen::Vector2d(start - left, 0));
      for (const Eigen::Vector2d& q : marker.placements[i].outline) right = std::max(right, q.x());
    }
    start = right + gap;
  }
  for (size_t i = 0; i < items.size(); ++i)
    if (items[i].binId() < 0)
      note_unplaced(marker, pattern.pieces[static_cast<size_t>(placements[i].piece)].label);
  measure_marker(marker);
  return marker;
}

}  // namespace qd::marker
