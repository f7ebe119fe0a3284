// Placing the flattened pieces side by side on one sheet, without overlap and at true scale
// (1 unit on the pattern = 1 unit on the mesh): each piece is moved rigidly, turned so its
// grainline (grainline.h) points along +y, as a marker lays every piece with its grain along
// the cloth's length, then the bounding boxes are packed in shelves, tallest first, each shelf
// filled left to right up to a width of 1.5·√(total box area) ("next-fit decreasing height",
// Coffman, Garey, Johnson & Tarjan 1980).
#pragma once

#include <Eigen/Geometry>
#include <vector>

namespace qd::flatten {

// The rotation that turns the unit direction `grain` onto +y.
Eigen::Matrix2d grain_rotation(const Eigen::Vector2d& grain);

// Lower-left corner of each box on the sheet: the boxes, grown by `gap` on their right and top,
// do not overlap. Depends on the boxes' sizes only, ties kept in input order.
std::vector<Eigen::Vector2d> shelf_pack(const std::vector<Eigen::AlignedBox2d>& boxes, double gap);

// The space between pieces on the sheet: gap when > 0, else 5 % of the largest box's longer side.
double sheet_gap(const std::vector<Eigen::AlignedBox2d>& boxes, double gap);

// Turns and packs every piece in place (one matrix of flat positions per piece, grain its unit
// grain direction) and returns each piece's box on the sheet. The boxes grown by `margin` (how
// far the cut lines reach outside, seam_allowance.h) keep `gap` apart; gap ≤ 0: 5 % of the
// largest piece's longer side.
std::vector<Eigen::AlignedBox2d> lay_out(std::vector<Eigen::MatrixX2d>& pieces,
                                         const std::vector<Eigen::Vector2d>& grain, double gap,
                                         double margin);

}  // namespace qd::flatten
