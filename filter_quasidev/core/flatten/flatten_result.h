// Output of the flattening: texture coordinates per face corner (wedge) in model units, the
// per-face stretch, one report per pattern piece, the pattern for the SVG/DXF writers and a log.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "flatten/pattern.h"
#include "flatten/symmetric_pieces.h"

namespace qd::flatten {

using WedgeUV = Eigen::Matrix<double, Eigen::Dynamic, 6>;  // per face: u0 v0 u1 v1 u2 v2

struct PieceReport {
  int patch = 0;
  int component = 0;  // 0, 1, … when the patch has several edge-connected components
  std::string label;  // as on the pattern
  int faces = 0;
  int vertices = 0;           // after cutting
  std::string cut;            // what was cut to make it a disk; empty if it was one (cut_to_disk.h)
  int iterations = 0;         // ARAP global steps
  std::string stop_reason;    // ARAP's
  double energy = 0;          // ARAP energy per unit area at the end
  double max_distortion = 0;  // percent (piece_measures.h)
  double mean_distortion = 0;  // percent, area-weighted
  double area_change = 0;      // percent
  double boundary_change = 0;  // percent
  int flipped = 0;
  int overlapping = 0;
  bool flattenable = true;  // no flipped and no overlapping faces: can be cut out as it is
  Eigen::AlignedBox2d box;  // where it lies on the sheet
  double time_ms = 0;
};

struct FlattenResult {
  WedgeUV uv;                       // one row per face of the input
  std::vector<double> stretch;      // per face: signed stretch (face_distortion.h)
  std::vector<PieceReport> pieces;  // by patch id, then component
  double max_distortion = 0;        // percent: the largest of the pieces'
  int flattenable_pieces = 0;       // pieces without flipped or overlapping faces
  std::vector<PieceGroup> groups;   // of congruent or mirror pieces, members index `pieces`
  Pattern pattern;                  // one piece per group, in the groups' order; where pieces were
                                    // grouped laid out anew (pattern_sheet.h), else as in `uv`
  std::vector<std::string> log;     // one line per piece, then a total
  double time_ms = 0;
};

}  // namespace qd::flatten
