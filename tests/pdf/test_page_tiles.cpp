// The tiling of a printed pattern onto pages (pdf/page_tiles.h) and the paper sizes (pdf/paper.h):
// the tiles cover the pattern with as few pages as possible, neighbours overlap by the stated
// amount, and the page names match their rows and columns.
#include <gtest/gtest.h>

#include "common/error.h"
#include "paper.h"

namespace qd::pdf {
namespace {

using namespace qd::common;

const Tile& at(const TileGrid& grid, int row, int column) {
  return grid.tiles[static_cast<std::size_t>(row * grid.columns + column)];
}

TEST(PageTiles, CoverThePatternWithTheFewestPagesAndOverlapNeighbours) {
  const PageSpec page = page_spec(params::Paper::A4);
  const double ppu = points_per_unit(params::PatternUnit::Centimetre);
  const Eigen::AlignedBox2d bounds(Eigen::Vector2d(-3, 2), Eigen::Vector2d(58, 41));  // cm
  const TileGrid grid = tile_pages(bounds, ppu, page);
  ASSERT_EQ(grid.tiles.size(), static_cast<std::size_t>(grid.rows * grid.columns));
  // 61 cm across 18 cm steps (19 cm of paper, 1 cm overlap): 4 columns; 39 cm down 26.7: 2 rows.
  EXPECT_EQ(grid.columns, 4);
  EXPECT_EQ(grid.rows, 2);
  Eigen::AlignedBox2d covered;
  for (const Tile& tile : grid.tiles) {
    EXPECT_NEAR(tile.area.sizes().x() * ppu, page.area_width(), 1e-6);
    EXPECT_NEAR(tile.area.sizes().y() * ppu, page.area_height(), 1e-6);
    covered.extend(tile.area);
  }
  EXPECT_TRUE(covered.contains(bounds));
  // One column or row fewer would not reach across.
  EXPECT_LT((grid.columns - 1) * (page.area_width() - page.overlap) + page.overlap,
            bounds.sizes().x() * ppu);
  EXPECT_LT((grid.rows - 1) * (page.area_height() - page.overlap) + page.overlap,
            bounds.sizes().y() * ppu);
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.columns; ++c) {
      const Tile& tile = at(grid, r, c);
      EXPECT_EQ(tile.row, r);
      EXPECT_EQ(tile.column, c);
      const double overlap = page.overlap / ppu;
      if (c > 0) {
        EXPECT_NEAR(at(grid, r, c - 1).area.max().x() - tile.area.min().x(), overlap, 1e-9);
      }
      if (r > 0) {  // row 0 is the top: a row starts above where the one over it ends
        EXPECT_NEAR(tile.area.max().y() - at(grid, r - 1, c).area.min().y(), overlap, 1e-9);
      }
    }
  EXPECT_NEAR(at(grid, 0, 0).area.min().x(), bounds.min().x(), 1e-9);
  EXPECT_NEAR(at(grid, 0, 0).area.max().y(), bounds.max().y(), 1e-9);
}

TEST(PageTiles, ASmallOrEmptyPatternIsOnePage) {
  const PageSpec page = page_spec(params::Paper::Letter);
  const Eigen::AlignedBox2d small(Eigen::Vector2d(0, 0), Eigen::Vector2d(7, 9));  // in
  EXPECT_EQ(tile_pages(small, 72, page).tiles.size(), 1u);
  EXPECT_EQ(tile_pages(Eigen::AlignedBox2d(), 72, page).tiles.size(), 1u);
  const Eigen::AlignedBox2d wider(Eigen::Vector2d(0, 0), Eigen::Vector2d(8, 9));  // > 7.7 in
  EXPECT_EQ(tile_pages(wider, 72, page).columns, 2);
}

TEST(PageTiles, NamesAreRowLettersAndColumnNumbers) {
  EXPECT_EQ((Tile{0, 0, {}}.name()), "A1");
  EXPECT_EQ((Tile{1, 2, {}}.name()), "B3");
  EXPECT_EQ((Tile{25, 0, {}}.name()), "Z1");
  EXPECT_EQ((Tile{26, 9, {}}.name()), "AA10");
}

TEST(Paper, SizesAndUnitsInPoints) {
  const PageSpec a4 = page_spec(params::Paper::A4), letter = page_spec(params::Paper::Letter);
  EXPECT_NEAR(a4.width, 595.28, 0.01);
  EXPECT_NEAR(a4.height, 841.89, 0.01);
  EXPECT_NEAR(letter.width, 612, 1e-9);
  EXPECT_NEAR(letter.height, 792, 1e-9);
  EXPECT_NEAR(points_per_unit(params::PatternUnit::Millimetre), 2.8346, 1e-4);
  EXPECT_NEAR(points_per_unit(params::PatternUnit::Centimetre), 28.346, 1e-3);
  EXPECT_NEAR(points_per_unit(params::PatternUnit::Inch), 72, 1e-9);
  EXPECT_THROW(points_per_unit(params::PatternUnit::Model), Error);
}

}  // namespace
}  // namespace qd::pdf
