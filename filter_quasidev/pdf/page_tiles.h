// The tiling of a pattern printed at true scale onto pages ("print at home" patterns): the grid
// of pages, and each page's rectangle in pattern coordinates, neighbours overlapping so the
// printed sheets can be aligned and taped. Pure geometry; lengths on paper in PostScript points
// (1 pt = 1/72 in, the PDF user unit: ISO 32000-1, 8.3.2.3).
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace qd::pdf {

constexpr double kPointsPerMm = 72.0 / 25.4;

// A portrait page: its size, the unprinted margin on each side and the overlap of neighbours.
struct PageSpec {
  double width = 0, height = 0;  // pt
  double margin = 10 * kPointsPerMm;
  double overlap = 10 * kPointsPerMm;
  double area_width() const { return width - 2 * margin; }  // the drawing area of a page
  double area_height() const { return height - 2 * margin; }
};

struct Tile {
  int row = 0, column = 0;   // row 0 is the top of the pattern, column 0 its left
  Eigen::AlignedBox2d area;  // what the page shows, in pattern (model) coordinates
  std::string name() const;  // "A1": row letter(s), column number
};

struct TileGrid {
  double points_per_unit = 1;  // the print scale: one model unit on paper
  int rows = 0, columns = 0;
  std::vector<Tile> tiles;              // row by row, left to right
  bool has(int row, int column) const;  // is that tile among `tiles`?
};

// The fewest pages of `page` that cover `bounds` (model units) at `points_per_unit`, each
// neighbour overlapping by page.overlap; an empty box is one page at the origin.
TileGrid tile_pages(const Eigen::AlignedBox2d& bounds, double points_per_unit,
                    const PageSpec& page);

// Leaves out the tiles that no piece's box reaches (the pieces lie in shelves, so a grid over
// their bounds has empty pages); the kept tiles keep their names, so neighbours still match.
void drop_empty_tiles(TileGrid& grid, const std::vector<Eigen::AlignedBox2d>& pieces);

}  // namespace qd::pdf
