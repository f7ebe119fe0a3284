// The cutting pattern: per piece its sew line(s) and cut line(s) on the sheet, its notches (the
// marks at seam vertices by which pieces are matched when sewn or joined), its grainline, its
// label and how many to cut. What the pattern writers draw; pure geometry, in model units.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "common/mesh.h"
#include "flatten/common_names.h"

namespace qd::flatten {

struct Notch {
  Eigen::Vector2d at;      // a boundary vertex on a seam or cut (notches.h), on the sew line
  Eigen::Vector2d inward;  // unit normal of the outline there, pointing into the piece
  Eigen::Vector2d cut_at;  // where it crosses the cut line: a notch is cut through the allowance
};

using Outline = std::vector<Eigen::Vector2d>;  // a closed polygon, its last point not repeated

struct PatternPiece {
  int patch = 0;
  std::string label;  // "3", or "3.1" for the second piece of patch 3
  std::string name;   // the panel's name in the input (OBJ group, PLY comment); "" = none
  std::vector<Outline> outlines;      // sew lines: counter-clockwise, one per boundary loop
  std::vector<Outline> cut_outlines;  // cut lines: the sew lines offset outward by the seam
                                      // allowance (seam_allowance.h); the sew lines when it is 0
  std::vector<Notch> notches;
  Eigen::Vector2d grain = Eigen::Vector2d::UnitY();  // unit direction of the grainline on the sheet
  Eigen::Vector2d label_at = Eigen::Vector2d::Zero();  // area centroid of the piece
  int quantity = 1;  // pieces to cut from this one (symmetric_pieces.h)
  int mirrored = 0;  // of which this many turned over (mirror images)
};

struct Pattern {
  std::vector<PatternPiece> pieces;
  Eigen::AlignedBox2d bounds;  // of every sew and cut line
};

// One piece: F its faces, uv its flat positions on the sheet, loops its boundary loops in face
// order, notch per vertex (1 = a notch where it is on a loop).
PatternPiece pattern_piece(int patch, const std::string& label, const Triangles& F,
                           const Eigen::MatrixX2d& uv, const std::vector<std::vector<int>>& loops,
                           const std::vector<char>& notch);

// The pattern of the given pieces, with its bounds (of sew and cut lines).
Pattern make_pattern(std::vector<PatternPiece> pieces);

}  // namespace qd::flatten
