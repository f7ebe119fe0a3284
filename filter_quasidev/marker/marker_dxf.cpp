#include "marker_dxf.h"

#include <set>
#include <string>

#include "io/dxf_groups.h"

namespace qd::marker {

namespace {

std::string layer_of(const flatten::PatternPiece& piece) {
  std::string layer = "PIECE_" + piece.label;
  for (char& c : layer)
    if (c == '.') c = '_';
  return layer;
}

}  // namespace

void write_marker_dxf(std::ostream& out, const Marker& marker, const flatten::Pattern& pattern) {
  std::set<std::string> names;
  for (const MarkerPlacement& p : marker.placements)
    names.insert(layer_of(pattern.pieces[static_cast<size_t>(p.piece)]));
  std::vector<io::DxfLayer> layers = {{"FABRIC", 5}};
  for (const std::string& name : names)
    layers.push_back({name, 1 + static_cast<int>(layers.size() - 1) % 7});
  const double w = marker.width, l = marker.length;
  io::DxfGroups g(out);
  g.header(Eigen::AlignedBox2d(Eigen::Vector2d::Zero(), Eigen::Vector2d(l, w)));
  g.tables(layers, 0.01 * w);
  g(0, "SECTION")(2, "ENTITIES");
  g.polyline("FABRIC", {{0, 0}, {l, 0}, {l, w}, {0, w}});
  for (const MarkerPlacement& p : marker.placements)
    g.polyline(layer_of(pattern.pieces[static_cast<size_t>(p.piece)]), p.outline);
  g(0, "ENDSEC")(0, "EOF");
}

}  // namespace qd::marker
