#include "page_tiles.h"

#include <algorithm>
#include <cmath>

namespace qd::pdf {

namespace {

// Pages of drawing length `area` with `overlap` that cover `length` (all in pt): n pages cover
// n * (area - overlap) + overlap.
int pages_along(double length, double area, double overlap) {
  return std::max(1, static_cast<int>(std::ceil((length - overlap) / (area - overlap) - 1e-9)));
}

}  // namespace

std::string Tile::name() const {
  std::string letters;
  for (int r = row + 1; r > 0; r = (r - 1) / 26)
    letters.insert(letters.begin(), static_cast<char>('A' + (r - 1) % 26));
  return letters + std::to_string(column + 1);
}

TileGrid tile_pages(const Eigen::AlignedBox2d& bounds, double points_per_unit,
                    const PageSpec& page) {
  const Eigen::AlignedBox2d box =
      bounds.isEmpty() ? Eigen::AlignedBox2d(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero())
                       : bounds;
  TileGrid grid;
  grid.points_per_unit = points_per_unit;
  const Eigen::Vector2d size = box.sizes() * points_per_unit;
  grid.columns = pages_along(size.x(), page.area_width(), page.overlap);
  grid.rows = pages_along(size.y(), page.area_height(), page.overlap);
  const Eigen::Vector2d area(page.area_width() / points_per_unit,
                             page.area_height() / points_per_unit);
  const Eigen::Vector2d step = area - Eigen::Vector2d::Constant(page.overlap / points_per_unit);
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.columns; ++c) {
      const Eigen::Vector2d top_left(box.min().x() + c * step.x(), box.max().y() - r * step.y());
      const Eigen::Vector2d min(top_left.x(), top_left.y() - area.y());
      grid.tiles.push_back({r, c, Eigen::AlignedBox2d(min, min + area)});
    }
  return grid;
}

bool TileGrid::has(int row, int column) const {
  return std::any_of(tiles.begin(), tiles.end(),
                     [&](const Tile& t) { return t.row == row && t.column == column; });
}

void drop_empty_tiles(TileGrid& grid, const std::vector<Eigen::AlignedBox2d>& pieces) {
  const auto empty = [&](const Tile& t) {
    return std::none_of(pieces.begin(), pieces.end(), [&](const Eigen::AlignedBox2d& b) {
      return !t.area.intersection(b).isEmpty();
    });
  };
  grid.tiles.erase(std::remove_if(grid.tiles.begin(), grid.tiles.end(), empty), grid.tiles.end());
}

}  // namespace qd::pdf
