#include "pdf_writer.h"

#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "common/error.h"
#include "common/format_text.h"
#include "io/piece_marks.h"

namespace qd::pdf {

namespace {

constexpr double kNotch = 5 * kPointsPerMm;  // how far a notch reaches into the piece
constexpr double kFont = 9, kSmallFont = 7;  // pt
constexpr double kCutLine = 0.8, kThinLine = 0.4;

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using Context = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// Pattern coordinates (y up, model units) to page points (y down): `origin` lands on `at`.
struct View {
  Eigen::Vector2d origin, at;
  double scale;  // pt per model unit
  Eigen::Vector2d operator()(const Eigen::Vector2d& p) const {
    return {at.x() + (p.x() - origin.x()) * scale, at.y() + (origin.y() - p.y()) * scale};
  }
};

void move_to(cairo_t* cr, const Eigen::Vector2d& p) { cairo_move_to(cr, p.x(), p.y()); }
void line_to(cairo_t* cr, const Eigen::Vector2d& p) { cairo_line_to(cr, p.x(), p.y()); }

void stroke_outlines(cairo_t* cr, const View& view, const std::vector<flatten::Outline>& outlines) {
  for (const flatten::Outline& outline : outlines) {
    for (std::size_t i = 0; i < outline.size(); ++i)
      (i == 0 ? move_to : line_to)(cr, view(outline[i]));
    cairo_close_path(cr);
  }
  cairo_stroke(cr);
}

// `text` with its baseline starting at (x, y), or centred on x.
void text(cairo_t* cr, const std::string& s, double x, double y, double size,
          bool centred = false) {
  cairo_set_font_size(cr, size);
  if (centred) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, s.c_str(), &extents);
    x -= extents.x_advance / 2;
  }
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, s.c_str());
}

// A double-headed arrow from a to b (page points).
void arrow(cairo_t* cr, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = (b - a).normalized() * 8, side(-d.y() * 0.4, d.x() * 0.4);
  move_to(cr, a);
  line_to(cr, b);
  const auto head = [cr, &side](const Eigen::Vector2d& tip, const Eigen::Vector2d& back) {
    move_to(cr, tip + back + side);
    line_to(cr, tip);
    line_to(cr, tip + back - side);
  };
  head(b, -d);
  head(a, d);
  cairo_stroke(cr);
}

// One piece at true scale: cut lines solid, sew lines dashed where they differ, notches through
// the allowance, grainline, label.
void draw_piece(cairo_t* cr, const View& view, const flatten::PatternPiece& piece,
                const std::string& unit) {
  cairo_set_line_width(cr, kCutLine);
  stroke_outlines(cr, view, piece.cut_outlines);
  if (piece.cut_outlines != piece.outlines) {
    const double dash[] = {4, 2};
    cairo_set_line_width(cr, kThinLine);
    cairo_set_dash(cr, dash, 2, 0);
    stroke_outlines(cr, view, piece.outlines);
    cairo_set_dash(cr, nullptr, 0, 0);
  }
  cairo_set_line_width(cr, kCutLine);
  for (const flatten::Notch& n : piece.notches) {
    const io::Segment2 tick = io::notch_tick(n, kNotch / view.scale);
    move_to(cr, view(tick.from));
    line_to(cr, view(tick.to));
  }
  cairo_stroke(cr);
  cairo_set_line_width(cr, kThinLine);
  const io::Segment2 grain = io::grainline(piece);
  if ((view(grain.to) - view(grain.from)).norm() > 20) arrow(cr, view(grain.from), view(grain.to));
  const std::vector<std::string> lines = io::label_lines(piece, unit, "\u00d7");
  const Eigen::Vector2d at = view(piece.label_at);
  for (size_t i = 0; i < lines.size(); ++i)
    text(cr, lines[i], at.x() + 4,
         at.y() +
             kFont * (1.2 * static_cast<double>(i) - 0.6 * static_cast<double>(lines.size() - 1)),
         kFont);
}

std::string page_line(int k, int n) { return common::format_text("page %d of %d", k, n); }

// A length on paper in mm, with `decimals` places.
std::string millimetres(double points, int decimals) {
  return common::format_text("%.*f", decimals, points / kPointsPerMm);
}

// Page 1: title, the whole pattern scaled into the space left above the test square, each
// tile's rectangle with its name and page number, and the test square.
void map_page(cairo_t* cr, const flatten::Pattern& pattern, const TileGrid& grid,
              const PageSpec& page) {
  const double top = page.margin + 3 * kFont,
               bottom = page.height - page.margin - kTestSquare - 2 * kFont;
  const Eigen::AlignedBox2d& first = grid.tiles.front().area;
  Eigen::AlignedBox2d all = first;
  for (const Tile& tile : grid.tiles) all.extend(tile.area);
  const double scale =
      std::min(page.area_width() / all.sizes().x(), (bottom - top) / all.sizes().y());
  const View view{{all.min().x(), all.max().y()}, {page.margin, top}, scale};
  const int pages = static_cast<int>(grid.tiles.size()) + 1;
  const Eigen::Vector2d size =
      pattern.bounds.isEmpty() ? Eigen::Vector2d::Zero() : Eigen::Vector2d(pattern.bounds.sizes());
  text(cr,
       "Assembly map: pattern " + millimetres(size.x() * grid.points_per_unit, 0) + " x " +
           millimetres(size.y() * grid.points_per_unit, 0) + " mm on " + std::to_string(grid.rows) +
           " x " + std::to_string(grid.columns) + " pages (rows x columns), overlapping " +
           millimetres(page.overlap, 0) + " mm",
       page.margin, page.margin + kFont, kFont);
  cairo_set_line_width(cr, kThinLine);
  for (const flatten::PatternPiece& piece : pattern.pieces)
    stroke_outlines(cr, view, piece.cut_outlines);
  cairo_set_source_rgb(cr, 0.2, 0.3, 0.8);
  for (std::size_t i = 0; i < grid.tiles.size(); ++i) {
    const Tile& tile = grid.tiles[i];
    const Eigen::Vector2d a = view({tile.area.min().x(), tile.area.max().y()});
    const Eigen::Vector2d b = view({tile.area.max().x(), tile.area.min().y()});
    cairo_rectangle(cr, a.x(), a.y(), b.x() - a.x(), b.y() - a.y());
    cairo_stroke(cr);
    const Eigen::Vector2d c = (a + b) / 2;
    const double font = std::min(kFont, (b.x() - a.x()) / 4);  // fits small cells
    text(cr, tile.name(), c.x(), c.y(), font, true);
    text(cr, "p." + std::to_string(i + 2), c.x(), c.y() + font, font, true);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  const double y = page.height - page.margin - kTestSquare;
  cairo_set_line_width(cr, kThinLine);
  cairo_rectangle(cr, page.margin, y, kTestSquare, kTestSquare);
  cairo_stroke(cr);
  text(cr, "this square measures 5 cm at 100 %", page.margin + kTestSquare + kFont, y + 2 * kFont,
       kFont);
  text(cr, "print at actual size (100 %), not fit to page", page.margin + kTestSquare + kFont,
       y + 4 * kFont, kSmallFont);
  text(cr, page_line(1, pages) + ": assembly map", page.width / 2, page.height - page.margin / 3,
       kSmallFont, true);
}

// Tile i: its share of the pattern clipped to the drawing area, the overlap borders (dashed)
// with the neighbours' names in the margins, its name and page number.
void tile_page(cairo_t* cr, const flatten::Pattern& pattern, const std::string& unit,
               const TileGrid& grid, const PageSpec& page, std::size_t i) {
  const Tile& tile = grid.tiles[i];
  const double left = page.margin, top = page.margin, right = page.width - page.margin,
               bottom = page.height - page.margin;
  cairo_save(cr);
  cairo_rectangle(cr, left, top, page.area_width(), page.area_height());
  cairo_clip(cr);
  const View view{{tile.area.min().x(), tile.area.max().y()}, {left, top}, grid.points_per_unit};
  for (const flatten::PatternPiece& piece : pattern.pieces) draw_piece(cr, view, piece, unit);
  cairo_restore(cr);

  cairo_set_source_rgb(cr, 0.5, 0.5, 0.5);
  cairo_set_line_width(cr, kThinLine);
  cairo_rectangle(cr, left, top, page.area_width(), page.area_height());
  cairo_stroke(cr);
  const double dash[] = {3, 3};
  cairo_set_dash(cr, dash, 2, 0);
  const auto neighbour = [](int r, int c) { return Tile{r, c, {}}.name(); };
  const double o = page.overlap, middle_y = (top + bottom) / 2, middle_x = (left + right) / 2;
  if (grid.has(tile.row, tile.column - 1)) {
    cairo_move_to(cr, left + o, top);
    cairo_line_to(cr, left + o, bottom);
    text(cr, neighbour(tile.row, tile.column - 1), left / 2, middle_y, kFont, true);
  }
  if (grid.has(tile.row, tile.column + 1)) {
    cairo_move_to(cr, right - o, top);
    cairo_line_to(cr, right - o, bottom);
    text(cr, neighbour(tile.row, tile.column + 1), (right + page.width) / 2, middle_y, kFont, true);
  }
  if (grid.has(tile.row - 1, tile.column)) {
    cairo_move_to(cr, left, top + o);
    cairo_line_to(cr, right, top + o);
    text(cr, neighbour(tile.row - 1, tile.column), middle_x, top / 2 + kFont / 2, kFont, true);
  }
  if (grid.has(tile.row + 1, tile.column)) {
    cairo_move_to(cr, left, bottom - o);
    cairo_line_to(cr, right, bottom - o);
    text(cr, neighbour(tile.row + 1, tile.column), middle_x, bottom + kFont, kFont, true);
  }
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, tile.name(), left, top - 3, kFont);
  text(cr,
       page_line(static_cast<int>(i) + 2, static_cast<int>(grid.tiles.size()) + 1) + " (row " +
           std::to_string(tile.row + 1) + ", column " + std::to_string(tile.column + 1) + ")",
       middle_x, page.height - page.margin / 3, kSmallFont, true);
}

}  // namespace

std::string pattern_pdf(const flatten::Pattern& pattern, const std::string& unit,
                        const TileGrid& grid, const PageSpec& page) {
  std::string bytes;
  {
    const Surface surface(
        cairo_pdf_surface_create_for_stream(append, &bytes, page.width, page.height),
        cairo_surface_destroy);
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE, "Cutting pattern");
    const Context cr(cairo_create(surface.get()), cairo_destroy);
    cairo_select_font_face(cr.get(), "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_line_join(cr.get(), CAIRO_LINE_JOIN_ROUND);
    map_page(cr.get(), pattern, grid, page);
    cairo_show_page(cr.get());
    for (std::size_t i = 0; i < grid.tiles.size(); ++i) {
      tile_page(cr.get(), pattern, unit, grid, page, i);
      cairo_show_page(cr.get());
    }
    cairo_surface_finish(surface.get());
    const cairo_status_t status = cairo_surface_status(surface.get());
    if (status != CAIRO_STATUS_SUCCESS)
      throw common::Error(std::string("could not draw the PDF: ") + cairo_status_to_string(status));
  }
  return bytes;
}

}  // namespace qd::pdf
