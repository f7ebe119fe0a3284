// Area, length and box of a piece's closed outlines (pattern.h), for the report and the writers:
// the shoelace formula for areas; the outer loop is the one enclosing the largest area, every other
// loop a hole. Model units.
#pragma once

#include <cstddef>
#include <vector>

#include "flatten/pattern.h"

namespace qd::flatten {

// Signed area of one closed polygon: positive when counter-clockwise.
double loop_area(const Outline& loop);

// Index of the loop enclosing the largest area (0 for no loops).
std::size_t outer_loop(const std::vector<Outline>& loops);

// The piece's area: the outer loop's less its holes'.
double outline_area(const std::vector<Outline>& loops);

// Length of every loop, holes included (closing edges included).
double outline_length(const std::vector<Outline>& loops);

// Bounding box of one loop's points, and of every loop's (empty for no points).
Eigen::AlignedBox2d loop_box(const Outline& loop);
Eigen::AlignedBox2d outline_box(const std::vector<Outline>& loops);

}  // namespace qd::flatten
