#include "marker.h"

#include <algorithm>
#include <cmath>

namespace qd::marker {

namespace {

double area(const flatten::Outline& o) {
  double a = 0;
  for (size_t i = 0, j = o.size() - 1; i < o.size(); j = i++)
    a += o[j].x() * o[i].y() - o[i].x() * o[j].y();
  return std::abs(a) / 2;
}

}  // namespace

void measure_marker(Marker& marker) {
  double pieces = 0;
  marker.length = 0;
  for (const MarkerPlacement& p : marker.placements) {
    pieces += area(p.outline);
    for (const Eigen::Vector2d& q : p.outline) marker.length = std::max(marker.length, q.x());
  }
  const double fabric = marker.width * marker.length;
  marker.efficiency = fabric > 0 ? pieces / fabric : 0;
}

void note_unplaced(Marker& marker, const std::string& label) {
  if (std::find(marker.unplaced.begin(), marker.unplaced.end(), label) == marker.unplaced.end())
    marker.unplaced.push_back(label);
}

}  // namespace qd::marker
