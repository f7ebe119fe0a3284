// A marker: the pattern's pieces laid out on a strip of fabric for cutting, the fabric's width
// along y and its length along x (the grain runs along the length). What the nesting makes and
// the marker writers draw; model units.
#pragma once

#include <string>
#include <vector>

#include "flatten/pattern.h"

namespace qd::marker {

struct MarkerPlacement {
  int piece = 0;          // index into Pattern::pieces
  bool mirrored = false;  // turned over (x -> -x on the sheet) before the rotation
  double rotation = 0;    // radians, counter-clockwise, from the sheet to the marker
  Eigen::Vector2d offset =
      Eigen::Vector2d::Zero();  // marker = rotation * (mirror * sheet) + offset
  flatten::Outline outline;     // the placed cut line
};

struct Marker {
  double width = 0, length = 0;
  double efficiency = 0;  // piece area / (width * length), 0..1
  std::vector<MarkerPlacement> placements;
  std::vector<std::string> unplaced;  // labels of the pieces wider than the fabric
};

// The length (largest x of the placed outlines) and the efficiency of a marker from its
// placements and width. Piece area: the area inside each placed cut line.
void measure_marker(Marker& marker);

// Adds a piece's label to Marker::unplaced, once.
void note_unplaced(Marker& marker, const std::string& label);

}  // namespace qd::marker
