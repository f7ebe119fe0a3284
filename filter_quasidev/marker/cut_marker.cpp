#include "cut_marker.h"

#include "nest_marker.h"
#include "row_marker.h"

namespace qd::marker {

MarkerChoice cut_marker(const flatten::Pattern& pattern, double width, double gap) {
  MarkerChoice c{nest_marker(pattern, width, gap), row_marker(pattern, width, gap)};
  // More pieces placed wins; among equal counts, the shorter.
  const size_t nested = c.nested.placements.size(), rows = c.rows.placements.size();
  c.nested_kept = nested != rows ? nested > rows : c.nested.length <= c.rows.length;
  return c;
}

}  // namespace qd::marker
