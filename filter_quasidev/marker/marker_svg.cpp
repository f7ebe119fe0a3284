#include "marker_svg.h"

#include <algorithm>
#include <locale>

#include "io/xml_text.h"

namespace qd::marker {

namespace {

constexpr double kMargin = 0.02, kStroke = 0.002, kFont = 0.03;  // of the fabric's width

}  // namespace

void write_marker_svg(std::ostream& out, const Marker& marker, const flatten::Pattern& pattern) {
  const std::locale previous = out.imbue(std::locale::classic());
  out.precision(8);
  const double margin = kMargin * marker.width;
  const auto x = [margin](const Eigen::Vector2d& p) { return p.x() + margin; };
  const auto y = [margin, &marker](const Eigen::Vector2d& p) {
    return marker.width - p.y() + margin;
  };
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" viewBox=\"0 0 "
      << marker.length + 2 * margin << ' ' << marker.width + 2 * margin << "\">\n"
      << "<title>Marker, width " << marker.width << ", length " << marker.length << ", efficiency "
      << 100 * marker.efficiency << " %</title>\n"
      << "<g fill=\"none\" stroke=\"black\" stroke-width=\"" << kStroke * marker.width
      << "\" font-family=\"sans-serif\" font-size=\"" << kFont * marker.width
      << "\" text-anchor=\"middle\" dominant-baseline=\"middle\">\n"
      << "<rect id=\"fabric\" x=\"" << margin << "\" y=\"" << margin << "\" width=\""
      << marker.length << "\" height=\"" << marker.width << "\" stroke=\"blue\"/>\n";
  for (const MarkerPlacement& p : marker.placements) {
    const std::string label = io::xml_escaped(pattern.pieces[static_cast<size_t>(p.piece)].label) +
                              (p.mirrored ? "m" : "");
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    out << "<g class=\"piece\" id=\"piece-" << label << "\">\n<path d=\"";
    for (size_t i = 0; i < p.outline.size(); ++i) {
      out << (i == 0 ? "M " : " L ") << x(p.outline[i]) << ' ' << y(p.outline[i]);
      centre += p.outline[i] / static_cast<double>(p.outline.size());
    }
    out << " Z\"/>\n<text x=\"" << x(centre) << "\" y=\"" << y(centre)
        << "\" stroke=\"none\" fill=\"black\">" << label << "</text>\n</g>\n";
  }
  out << "</g>\n</svg>\n";
  out.imbue(previous);
}

}  // namespace qd::marker
