// The pattern as a printable PDF at true scale, drawn with cairo's PDF surface (cairo 1.16,
// https://www.cairographics.org/manual/cairo-PDF-Surfaces.html). Page 1: the assembly map (the
// whole pattern with the page grid, each page's name and number) and a 50 mm test square to
// check the printer's scale. Then one page per tile of the grid: its part of the pattern (cut
// lines solid, sew lines dashed, notches, grainlines, labels), the overlap borders with the
// neighbours' names, and "page k of n (row r, column c)".
#pragma once

#include <string>

#include "flatten/pattern.h"
#include "page_tiles.h"

namespace qd::pdf {

constexpr double kTestSquare = 50 * kPointsPerMm;  // the test square's side, pt

// The PDF document's bytes; unit: the model's length unit for the pieces' sizes; grid =
// tile_pages(pattern.bounds, ..., page). Throws qd::common::Error if cairo fails.
std::string pattern_pdf(const flatten::Pattern& pattern, const std::string& unit,
                        const TileGrid& grid, const PageSpec& page);

}  // namespace qd::pdf
