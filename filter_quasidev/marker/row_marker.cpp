#include "row_marker.h"

#include <algorithm>

#include "flatten/outline_measures.h"
#include "marker_items.h"

namespace qd::marker {

Marker row_marker(const flatten::Pattern& pattern, double width, double gap) {
  Marker marker;
  marker.width = width;
  std::vector<MarkerPlacement> items = marker_items(pattern);
  std::stable_sort(
      items.begin(), items.end(), [](const MarkerPlacement& a, const MarkerPlacement& b) {
        return flatten::loop_box(a.outline).sizes().x() > flatten::loop_box(b.outline).sizes().x();
      });
  double row_x = 0, row_length = 0, y = 0;
  for (MarkerPlacement& p : items) {
    const Eigen::AlignedBox2d box = flatten::loop_box(p.outline);
    if (box.sizes().y() > width) {
      note_unplaced(marker, pattern.pieces[static_cast<size_t>(p.piece)].label);
      continue;
    }
    if (y > 0 && y + box.sizes().y() > width) {  // a new row
      row_x += row_length + gap;
      row_length = 0;
      y = 0;
    }
    translate_placement(p, Eigen::Vector2d(row_x, y) - box.min());
    row_length = std::max(row_length, box.sizes().x());
    y += box.sizes().y() + gap;
    marker.placements.push_back(std::move(p));
  }
  measure_marker(marker);
  return marker;
}

}  // namespace qd::marker
