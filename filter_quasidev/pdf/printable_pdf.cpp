#include "printable_pdf.h"

#include "common/error.h"
#include "io/piece_marks.h"
#include "paper.h"
#include "pdf_writer.h"

namespace qd::pdf {

PrintablePdf printable_pdf(const flatten::Pattern& pattern, params::Paper paper,
                           params::PatternUnit unit) {
  const PageSpec page = page_spec(paper);
  TileGrid grid = tile_pages(pattern.bounds, points_per_unit(unit), page);
  const size_t all = grid.tiles.size();
  std::vector<Eigen::AlignedBox2d> boxes;
  for (const flatten::PatternPiece& piece : pattern.pieces) boxes.push_back(io::cut_box(piece));
  drop_empty_tiles(grid, boxes);
  const std::string pages = std::to_string(grid.tiles.size() + 1);
  const std::string layout = std::to_string(grid.tiles.size()) + " tiles of a " +
                             std::to_string(grid.rows) + " x " + std::to_string(grid.columns) +
                             " grid, " + std::to_string(all - grid.tiles.size()) +
                             " empty left out";
  if (grid.tiles.size() + 1 > kMaxPages)
    throw common::Error("the printable PDF would take " + pages + " pages (" + layout +
                        "): is --unit the model's unit?");
  return {pattern_pdf(pattern, name_of(params::kPatternUnits, unit), grid, page),
          "pdf: " + pages + " pages of " + params::name_of(params::kPapers, paper) +
              " (assembly map + " + layout + ")"};
}

}  // namespace qd::pdf
