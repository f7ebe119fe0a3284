// Placing the flattened pieces side by side on one sheet, without overlap and at true scale
// (1 unit on the pattern = 1 unit on the mesh): each piece is moved rigidly, turned so its
// principal axis (of its vertices' covariance) runs along x, then the bounding boxes are
// packed in shelves, tallest first, each shelf filled left to right up to a width of
// 1.5·√(total box area) ("next-fit decreasing height", Coffman, Garey, Johnson & Tarjan 1980).
#pragma once

#include <Eigen/Geometry>
#include <vector>

namespace qd {

// The rotation that turns the principal axis of the points (rows) onto the x axis.
Eigen::Matrix2d principal_rotation(const Eigen::MatrixX2d& points);

// Lower-left corner of each box on the sheet: the boxes, grown by `gap` on their right and top,
// do not overlap. Depends on the boxes' sizes only, ties kept in input order.
std::vector<Eigen::Vector2d> shelf_pack(const std::vector<Eigen::AlignedBox2d>& boxes, double gap);

// Turns and packs every piece in place (one matrix of flat positions per piece) and returns
// each piece's box on the sheet. gap ≤ 0: 5 % of the largest piece's longer side.
std::vector<Eigen::AlignedBox2d> lay_out(std::vector<Eigen::MatrixX2d>& pieces, double gap);

}  // namespace qd
