#include "io/dxf_writer.h"

#include <set>

#include "io/dxf_groups.h"
#include "io/piece_marks.h"

namespace qd::io {

namespace {

constexpr double kNotch = 0.012, kText = 0.025;  // of the pattern's longer side, as in the SVG

std::string layer_of(int patch) { return "PATCH_" + std::to_string(patch); }
std::string sew_layer_of(int patch) { return layer_of(patch) + "_SEW"; }
std::string notch_layer_of(int patch) { return layer_of(patch) + "_NOTCHES"; }
std::string grain_layer_of(int patch) { return layer_of(patch) + "_GRAIN"; }

std::vector<DxfLayer> layers_of(const flatten::Pattern& pattern) {
  std::set<int> patches;
  for (const flatten::PatternPiece& piece : pattern.pieces) patches.insert(piece.patch);
  std::vector<DxfLayer> layers;
  int colour = 0;
  for (const int patch : patches) {
    const int c = 1 + colour++ % 7;
    layers.push_back({layer_of(patch), c, false});
    layers.push_back({sew_layer_of(patch), c, true});
    layers.push_back({notch_layer_of(patch), c, false});
    layers.push_back({grain_layer_of(patch), c, false});
  }
  return layers;
}

void piece_entities(DxfGroups& g, const flatten::PatternPiece& piece, const std::string& unit,
                    double notch, double text) {
  const std::string layer = layer_of(piece.patch);
  for (const flatten::Outline& loop : piece.cut_outlines) g.polyline(layer, loop);
  if (piece.cut_outlines != piece.outlines)
    for (const flatten::Outline& loop : piece.outlines) g.polyline(sew_layer_of(piece.patch), loop);
  for (const flatten::Notch& n : piece.notches) {
    const Segment2 tick = notch_tick(n, notch);
    g.line(notch_layer_of(piece.patch), tick.from, tick.to);
  }
  const Segment2 grain = grainline(piece);
  g.line(grain_layer_of(piece.patch), grain.from, grain.to);
  const std::vector<std::string> lines = label_lines(piece, unit, "x");
  g.text_lines(layer, piece.label_at, label_height(piece, lines, text), lines);
}

}  // namespace

void write_dxf(std::ostream& out, const flatten::Pattern& pattern, const std::string& unit) {
  DxfGroups g(out);
  const Eigen::AlignedBox2d bounds =
      pattern.bounds.isEmpty()
          ? Eigen::AlignedBox2d(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero())
          : pattern.bounds;
  const double side = bounds.sizes().maxCoeff();
  g.header(bounds);
  g.tables(layers_of(pattern), kNotch * side);
  g(0, "SECTION")(2, "ENTITIES");
  for (const flatten::PatternPiece& piece : pattern.pieces)
    piece_entities(g, piece, unit, kNotch * side, kText * side);
  g(0, "ENDSEC")(0, "EOF");
}

}  // namespace qd::io
