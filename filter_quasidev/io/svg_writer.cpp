#include "io/svg_writer.h"

#include <algorithm>
#include <cmath>
#include <locale>
#include <utility>
#include <vector>

#include "common/format_text.h"
#include "io/piece_marks.h"
#include "io/xml_text.h"

namespace qd::io {

namespace {

// Sizes of the drawing's furniture, as fractions of the pattern's longer side.
constexpr double kMargin = 0.04, kStroke = 0.002, kNotch = 0.012, kFont = 0.025, kScaleBar = 0.25;

// The largest 1, 2 or 5 times a power of ten not above x (> 0).
double round_length(double x) {
  const double power = std::pow(10.0, std::floor(std::log10(x)));
  for (const double m : {5.0, 2.0})
    if (m * power <= x) return m * power;
  return power;
}

// Pattern coordinates to the document's (y flipped, margin added).
struct Page {
  Eigen::AlignedBox2d bounds;
  double margin;
  double x(const Eigen::Vector2d& p) const { return p.x() - bounds.min().x() + margin; }
  double y(const Eigen::Vector2d& p) const { return bounds.max().y() - p.y() + margin; }
};

// "x y" of p on the page.
struct At {
  const Page& page;
  Eigen::Vector2d p;
};
std::ostream& operator<<(std::ostream& out, const At& at) {
  return out << at.page.x(at.p) << ' ' << at.page.y(at.p);
}

void write_loops(std::ostream& out, const std::vector<flatten::Outline>& loops, const Page& page) {
  for (const auto& loop : loops) {
    for (size_t i = 0; i < loop.size(); ++i) out << (i == 0 ? "M " : " L ") << At{page, loop[i]};
    out << " Z ";
  }
}

// The grainline with an arrowhead of length `head` at both ends.
void write_grainline(std::ostream& out, const flatten::PatternPiece& piece, const Page& page,
                     double head) {
  const Segment2 g = grainline(piece);
  const Eigen::Vector2d along = piece.grain * head, across(-along.y(), along.x());
  out << "<path class=\"grain\" d=\"M " << At{page, g.from} << " L " << At{page, g.to};
  using TipBack = std::pair<Eigen::Vector2d, Eigen::Vector2d>;
  for (const auto& [tip, back] : {TipBack(g.to, -along), TipBack(g.from, along)})
    out << " M " << At{page, tip + back + across / 2} << " L " << At{page, tip} << " L "
        << At{page, tip + back - across / 2};
  out << "\"/>\n";
}

void write_piece(std::ostream& out, const flatten::PatternPiece& piece, const Page& page,
                 double notch, double font, const std::string& unit) {
  out << "<g id=\"piece-" << xml_escaped(piece.label) << "\">\n<path class=\"cut\" d=\"";
  write_loops(out, piece.cut_outlines, page);
  out << "\"/>\n";
  if (piece.cut_outlines != piece.outlines) {
    out << "<path class=\"sew\" stroke-dasharray=\"" << notch << ' ' << notch / 2 << "\" d=\"";
    write_loops(out, piece.outlines, page);
    out << "\"/>\n";
  }
  if (!piece.notches.empty()) {
    out << "<path class=\"notches\" d=\"";
    for (const flatten::Notch& n : piece.notches) {
      const Segment2 tick = notch_tick(n, notch);
      out << "M " << At{page, tick.from} << " L " << At{page, tick.to} << ' ';
    }
    out << "\"/>\n";
  }
  write_grainline(out, piece, page, notch);
  const std::vector<std::string> lines = label_lines(piece, unit, "\u00d7");
  const double size = label_height(piece, lines, font);
  const double top = page.y(piece.label_at) - 0.6 * size * static_cast<double>(lines.size() - 1);
  for (size_t i = 0; i < lines.size(); ++i)
    out << "<text x=\"" << page.x(piece.label_at) << "\" y=\""
        << top + 1.2 * size * static_cast<double>(i) << "\" font-size=\"" << size
        << "\" stroke=\"none\" fill=\"black\">" << xml_escaped(lines[i]) << "</text>\n";
  out << "</g>\n";
}

}  // namespace

void write_svg(std::ostream& out, const flatten::Pattern& pattern, const std::string& unit) {
  const std::locale previous = out.imbue(std::locale::classic());
  const Eigen::AlignedBox2d bounds =
      pattern.bounds.isEmpty()
          ? Eigen::AlignedBox2d(Eigen::Vector2d::Zero(), Eigen::Vector2d::Ones())
          : pattern.bounds;
  const double side = std::max(bounds.sizes().maxCoeff(), 1e-300);
  const Page page{bounds, kMargin * side};
  const double font = kFont * side;
  const double width = bounds.sizes().x() + 2 * page.margin;
  const double height = bounds.sizes().y() + 2 * page.margin + 3 * font;  // the scale bar below
  const bool physical = unit == "mm" || unit == "cm" || unit == "in";
  out.precision(8);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"";
  if (physical) out << " width=\"" << width << unit << "\" height=\"" << height << unit << "\"";
  out << " viewBox=\"0 0 " << width << ' ' << height << "\">\n"
      << "<title>Cutting pattern, 1 unit = 1 model unit</title>\n"
      << "<g fill=\"none\" stroke=\"black\" stroke-width=\"" << kStroke * side
      << "\" font-family=\"sans-serif\" font-size=\"" << font
      << "\" text-anchor=\"middle\" dominant-baseline=\"middle\">\n";
  for (const flatten::PatternPiece& piece : pattern.pieces)
    write_piece(out, piece, page, kNotch * side, font, unit);
  const double bar = round_length(
      kScaleBar * bounds.sizes().x() > 0 ? kScaleBar * bounds.sizes().x() : kScaleBar * side);
  const double x = page.margin, y = height - page.margin - font;
  out << "<g id=\"scale-bar\">\n<path d=\"M " << x << ' ' << y - font / 2 << " L " << x << ' ' << y
      << " L " << x + bar << ' ' << y << " L " << x + bar << ' ' << y - font / 2 << "\"/>\n"
      << "<text x=\"" << x + bar / 2 << "\" y=\"" << y + font
      << "\" stroke=\"none\" fill=\"black\">"
      << xml_escaped(common::format_text("%g %s", bar, unit.empty() ? "model units" : unit.c_str()))
      << "</text>\n</g>\n</g>\n</svg>\n";
  out.imbue(previous);
}

}  // namespace qd::io
