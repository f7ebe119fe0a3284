// The cutting pattern: per piece its outline(s) on the sheet, its label and its notches, the
// marks at seam vertices by which pieces are matched when sewn or joined. What the SVG and DXF
// writers draw; pure geometry, in model units.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "common/mesh.h"

namespace qd {

struct Notch {
  Eigen::Vector2d at;      // a boundary vertex on a seam or cut (notches.h)
  Eigen::Vector2d inward;  // unit normal of the outline there, pointing into the piece
};

struct PatternPiece {
  int patch = 0;
  std::string label;                                   // "3", or "3.1" for the second piece of patch 3
  std::vector<std::vector<Eigen::Vector2d>> outlines;  // closed, counter-clockwise, one per boundary loop
  std::vector<Notch> notches;
  Eigen::Vector2d label_at = Eigen::Vector2d::Zero();  // area centroid of the piece
};

struct Pattern {
  std::vector<PatternPiece> pieces;
  Eigen::AlignedBox2d bounds;  // of every outline
};

// One piece: F its faces, uv its flat positions on the sheet, loops its boundary loops in face
// order, notch per vertex (1 = a notch where it is on a loop).
PatternPiece pattern_piece(int patch, const std::string& label, const Triangles& F, const Eigen::MatrixX2d& uv,
                           const std::vector<std::vector<int>>& loops, const std::vector<char>& notch);

// The pattern of the given pieces, with its bounds.
Pattern make_pattern(std::vector<PatternPiece> pieces);

}  // namespace qd
