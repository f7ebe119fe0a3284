#include "printable_pdf.h"

#include "common/error.h"
#include "paper.h"
#include "pdf_writer.h"

namespace qd::pdf {

PrintablePdf printable_pdf(const Pattern& pattern, params::Paper paper, params::PatternUnit unit) {
  const PageSpec page = page_spec(paper);
  const TileGrid grid = tile_pages(pattern.bounds, points_per_unit(unit), page);
  const std::string pages = std::to_string(grid.tiles.size() + 1);
  const std::string layout =
      std::to_string(grid.rows) + " rows x " + std::to_string(grid.columns) + " columns of tiles";
  if (grid.tiles.size() + 1 > kMaxPages)
    throw Error("the printable PDF would take " + pages + " pages (" + layout +
                "): is --unit the model's unit?");
  return {pattern_pdf(pattern, grid, page), "pdf: " + pages + " pages of " +
                                                params::name_of(params::kPapers, paper) +
                                                " (assembly map + " + layout + ")"};
}

}  // namespace qd::pdf
