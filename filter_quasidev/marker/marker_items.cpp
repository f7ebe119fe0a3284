#include "marker_items.h"

#include <algorithm>
#include <cmath>

namespace qd::marker {

namespace {

MarkerPlacement item(const flatten::Pattern& pattern, int index, bool mirrored) {
  const flatten::PatternPiece& piece = pattern.pieces[static_cast<size_t>(index)];
  const Eigen::Vector2d flip(mirrored ? -1 : 1, 1);
  const Eigen::Vector2d grain = piece.grain.cwiseProduct(flip);
  MarkerPlacement p;
  p.piece = index;
  p.mirrored = mirrored;
  p.rotation = -std::atan2(grain.y(), grain.x());  // the grain onto +x
  const Eigen::Rotation2Dd turn(p.rotation);
  for (const Eigen::Vector2d& q : piece.cut_outlines.front())
    p.outline.push_back(turn * q.cwiseProduct(flip));
  if (mirrored) std::reverse(p.outline.begin(), p.outline.end());  // counter-clockwise again
  return p;
}

}  // namespace

std::vector<MarkerPlacement> marker_items(const flatten::Pattern& pattern) {
  std::vector<MarkerPlacement> items;
  for (int i = 0; i < static_cast<int>(pattern.pieces.size()); ++i) {
    const flatten::PatternPiece& piece = pattern.pieces[static_cast<size_t>(i)];
    if (piece.cut_outlines.empty() || piece.cut_outlines.front().size() < 3) continue;
    for (int copy = 0; copy < piece.quantity; ++copy)
      items.push_back(item(pattern, i, copy < piece.mirrored));
  }
  return items;
}

void translate_placement(MarkerPlacement& p, const Eigen::Vector2d& d) {
  p.offset += d;
  for (Eigen::Vector2d& q : p.outline) q += d;
}

}  // namespace qd::marker
