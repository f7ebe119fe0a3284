#include "marker_dxf.h"

#include <iomanip>
#include <locale>
#include <set>
#include <string>

namespace qd {

namespace {

// A DXF group: its code, then its value, one line each.
template <typename Value>
void group(std::ostream& out, int code, const Value& value) {
  out << std::setw(3) << code << '\n' << value << '\n';
}

void polyline(std::ostream& out, const std::string& layer, const Outline& outline) {
  group(out, 0, "POLYLINE");
  group(out, 8, layer);
  group(out, 66, 1);
  group(out, 70, 1);  // closed
  for (const Eigen::Vector2d& p : outline) {
    group(out, 0, "VERTEX");
    group(out, 8, layer);
    group(out, 10, p.x());
    group(out, 20, p.y());
    group(out, 30, 0.0);
  }
  group(out, 0, "SEQEND");
  group(out, 8, layer);
}

std::string layer_of(const PatternPiece& piece) {
  std::string layer = "PIECE_" + piece.label;
  for (char& c : layer)
    if (c == '.') c = '_';
  return layer;
}

}  // namespace

void write_marker_dxf(std::ostream& out, const Marker& marker, const Pattern& pattern) {
  const std::locale previous = out.imbue(std::locale::classic());
  const auto precision = out.precision(10);
  std::set<std::string> layers = {"FABRIC"};
  for (const MarkerPlacement& p : marker.placements)
    layers.insert(layer_of(pattern.pieces[static_cast<size_t>(p.piece)]));
  group(out, 0, "SECTION");
  group(out, 2, "HEADER");
  group(out, 9, "$ACADVER");
  group(out, 1, "AC1009");
  group(out, 0, "ENDSEC");
  group(out, 0, "SECTION");
  group(out, 2, "TABLES");
  group(out, 0, "TABLE");
  group(out, 2, "LAYER");
  group(out, 70, layers.size());
  int colour = 0;
  for (const std::string& layer : layers) {
    group(out, 0, "LAYER");
    group(out, 2, layer);
    group(out, 70, 0);
    group(out, 62, 1 + colour++ % 7);
    group(out, 6, "CONTINUOUS");
  }
  group(out, 0, "ENDTAB");
  group(out, 0, "ENDSEC");
  group(out, 0, "SECTION");
  group(out, 2, "ENTITIES");
  const double w = marker.width, l = marker.length;
  polyline(out, "FABRIC", {{0, 0}, {l, 0}, {l, w}, {0, w}});
  for (const MarkerPlacement& p : marker.placements)
    polyline(out, layer_of(pattern.pieces[static_cast<size_t>(p.piece)]), p.outline);
  group(out, 0, "ENDSEC");
  group(out, 0, "EOF");
  out.precision(precision);
  out.imbue(previous);
}

}  // namespace qd
