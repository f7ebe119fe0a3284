#include "io/aama_dxf_writer.h"

#include "common/error.h"
#include "flatten/outline_measures.h"
#include "io/dxf_groups.h"
#include "io/piece_marks.h"

namespace qd::io {

namespace {

constexpr double kNotch = 0.012, kText = 0.025;  // of the pattern's longer side, as in the SVG
const std::string kBoundary = "1", kNotches = "4", kGrain = "7", kCutOuts = "11", kSew = "14",
                  kAnnotation = "15";

// How the file writes the model's unit: the factor to its unit, that unit, metric or not.
struct FileUnit {
  double scale;
  std::string name;
  bool metric;
};

FileUnit file_unit(const std::string& unit) {
  if (unit == "mm") return {1, "mm", true};
  if (unit == "cm") return {10, "mm", true};
  if (unit == "in") return {1, "in", false};
  throw common::Error("an AAMA DXF needs the pattern's unit (mm, cm or in), not '" +
                      (unit.empty() ? std::string("model") : unit) + "'");
}

// The piece moved by −origin and scaled: what its block holds.
flatten::PatternPiece in_block(flatten::PatternPiece piece, const Eigen::Vector2d& origin,
                               double scale) {
  const auto place = [&](Eigen::Vector2d& p) { p = scale * (p - origin); };
  for (auto* loops : {&piece.outlines, &piece.cut_outlines})
    for (flatten::Outline& loop : *loops)
      for (Eigen::Vector2d& p : loop) place(p);
  for (flatten::Notch& n : piece.notches) {
    place(n.at);
    place(n.cut_at);
  }
  place(piece.label_at);
  return piece;
}

std::string block_name(const flatten::PatternPiece& piece) {
  std::string name = "PIECE_" + piece.label;
  for (char& c : name)
    if (c == '.') c = '_';
  return name;
}

void block(DxfGroups& g, const flatten::PatternPiece& piece, const std::string& unit, double notch,
           double text) {
  const std::string name = block_name(piece);
  g(0, "BLOCK")(8, "0")(2, name)(70, 0).point(10, Eigen::Vector2d::Zero())(3, name);
  const std::size_t outer = flatten::outer_loop(piece.cut_outlines);
  for (std::size_t i = 0; i < piece.cut_outlines.size(); ++i)
    g.polyline(i == outer ? kBoundary : kCutOuts, piece.cut_outlines[i]);
  if (piece.cut_outlines != piece.outlines)
    for (const flatten::Outline& loop : piece.outlines) g.polyline(kSew, loop);
  for (const flatten::Notch& n : piece.notches) {
    const Segment2 tick = notch_tick(n, notch);
    g.line(kNotches, tick.from, tick.to);
  }
  const Segment2 grain = grainline(piece);
  g.line(kGrain, grain.from, grain.to);
  const Eigen::AlignedBox2d box = cut_box(piece);
  const Eigen::Vector2d below(box.center().x(), box.min().y() - 2 * text);
  g.text_lines(kBoundary, below, text,
               {"Piece Name: " + (piece.name.empty() ? "Piece " + piece.label : piece.name),
                "Quantity: " + std::to_string(piece.quantity)});
  const std::vector<std::string> lines = label_lines(piece, unit, "x");
  g.text_lines(kAnnotation, piece.label_at, label_height(piece, lines, text), lines);
  g(0, "ENDBLK")(8, "0");
}

}  // namespace

void write_aama_dxf(std::ostream& out, const flatten::Pattern& pattern, const std::string& unit) {
  const FileUnit u = file_unit(unit);
  DxfGroups g(out);
  const Eigen::AlignedBox2d bounds =
      pattern.bounds.isEmpty()
          ? Eigen::AlignedBox2d(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero())
          : pattern.bounds;
  const Eigen::AlignedBox2d extents(u.scale * bounds.min(), u.scale * bounds.max());
  const double side = extents.sizes().maxCoeff();
  g.header(extents, u.metric ? 1 : 0);
  g.tables({{kBoundary, 7, false},
            {kNotches, 1, false},
            {kGrain, 3, false},
            {kCutOuts, 7, false},
            {kSew, 5, true},
            {kAnnotation, 4, false}},
           kNotch * side);
  std::vector<Eigen::Vector2d> origins;
  g(0, "SECTION")(2, "BLOCKS");
  for (const flatten::PatternPiece& piece : pattern.pieces) {
    const Eigen::AlignedBox2d box = cut_box(piece);
    origins.push_back(box.isEmpty() ? Eigen::Vector2d::Zero() : box.min());
    block(g, in_block(piece, origins.back(), u.scale), u.name, kNotch * side, kText * side);
  }
  g(0, "ENDSEC")(0, "SECTION")(2, "ENTITIES");
  const Eigen::Vector2d below(extents.min().x(), extents.min().y() - 4 * kText * side);
  g.text_lines(kBoundary, below, kText * side,
               {std::string("Units: ") + (u.metric ? "METRIC" : "ENGLISH")});
  for (std::size_t i = 0; i < pattern.pieces.size(); ++i)
    g(0, "INSERT")(8, "0")(2, block_name(pattern.pieces[i])).point(10, u.scale * origins[i]);
  g(0, "ENDSEC")(0, "EOF");
}

}  // namespace qd::io
