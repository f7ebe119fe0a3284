#include "io/piece_marks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "common/format_text.h"
#include "flatten/outline_measures.h"

namespace qd::io {

namespace {

constexpr double kGrainShare = 0.6;  // of the piece's extent along the grain
constexpr double kInside = 0.9;      // of the way from the centroid to the sew line

// x rounded to hundredths, as text.
// Characters of a UTF-8 text (its bytes less the continuation bytes).
size_t characters(const std::string& text) {
  return static_cast<size_t>(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

std::string measure_text(double x) {
  return common::format_text("%.12g", std::round(x * 100) / 100);
}

// How far from `at` along ±d the line first crosses the loops: {before (≤ 0), after (≥ 0)},
// infinite where it does not.
std::pair<double, double> crossings(const std::vector<flatten::Outline>& loops,
                                    const Eigen::Vector2d& at, const Eigen::Vector2d& d) {
  double before = -std::numeric_limits<double>::infinity();
  double after = std::numeric_limits<double>::infinity();
  for (const flatten::Outline& loop : loops)
    for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
      const Eigen::Vector2d a = loop[i] - at, e = loop[(i + 1) % n] - loop[i];
      const double det = e.x() * d.y() - e.y() * d.x();  // solve t d = a + s e
      if (det == 0) continue;
      const double s = (a.y() * d.x() - a.x() * d.y()) / det;
      if (s < 0 || s > 1) continue;
      const double t = (a + s * e).dot(d);
      if (t >= 0) after = std::min(after, t);
      if (t <= 0) before = std::max(before, t);
    }
  return {before, after};
}

}  // namespace

Eigen::AlignedBox2d cut_box(const flatten::PatternPiece& piece) {
  return flatten::outline_box(piece.cut_outlines);
}

Segment2 grainline(const flatten::PatternPiece& piece) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const flatten::Outline& loop : piece.cut_outlines)
    for (const Eigen::Vector2d& p : loop) {
      low = std::min(low, p.dot(piece.grain));
      high = std::max(high, p.dot(piece.grain));
    }
  const double half = high > low ? kGrainShare * (high - low) / 2 : 0;
  const auto [before, after] = crossings(piece.outlines, piece.label_at, piece.grain);
  return {piece.label_at + std::max(-half, kInside * before) * piece.grain,
          piece.label_at + std::min(half, kInside * after) * piece.grain};
}

Segment2 notch_tick(const flatten::Notch& notch, double beyond) {
  return {notch.cut_at, notch.at + beyond * notch.inward};
}

std::vector<std::string> label_lines(const flatten::PatternPiece& piece, const std::string& unit,
                                     const std::string& times) {
  std::vector<std::string> lines;
  if (!piece.name.empty()) lines.push_back(piece.name);
  lines.push_back("Piece " + piece.label);
  std::string cut = "Cut " + std::to_string(piece.quantity);
  if (piece.mirrored > 0) cut += " (" + std::to_string(piece.mirrored) + " mirrored)";
  lines.push_back(cut);
  const Eigen::AlignedBox2d box = cut_box(piece);
  if (!box.isEmpty())
    lines.push_back(measure_text(box.sizes().x()) + " " + times + " " +
                    measure_text(box.sizes().y()) + " " + (unit.empty() ? "model units" : unit));
  return lines;
}

double label_height(const flatten::PatternPiece& piece, const std::vector<std::string>& lines,
                    double height) {
  const Eigen::AlignedBox2d box = flatten::outline_box(piece.outlines);
  size_t longest = 1;
  for (const std::string& line : lines) longest = std::max(longest, characters(line));
  const double fit_x = 0.8 * box.sizes().x() / (0.6 * static_cast<double>(longest));
  const double fit_y =
      0.5 * box.sizes().y() / (1.2 * static_cast<double>(std::max<size_t>(lines.size(), 1)));
  return std::min(height, std::min(fit_x, fit_y));
}

}  // namespace qd::io
