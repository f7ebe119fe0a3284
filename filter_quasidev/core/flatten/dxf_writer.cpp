#include "flatten/dxf_writer.h"

#include <algorithm>
#include <iomanip>
#include <locale>
#include <set>
#include <string>

namespace qd {

namespace {

constexpr double kNotch = 0.012, kText = 0.025;  // of the pattern's longer side, as in the SVG

// Writes DXF group-code/value pairs, one per two lines.
class Groups {
 public:
  explicit Groups(std::ostream& out) : out_(out) {}
  Groups& operator()(int code, const std::string& value) {
    out_ << std::setw(3) << code << '\n' << value << '\n';
    return *this;
  }
  Groups& operator()(int code, double value) {
    out_ << std::setw(3) << code << '\n' << value << '\n';
    return *this;
  }
  Groups& operator()(int code, int value) {
    out_ << std::setw(3) << code << '\n' << std::setw(6) << value << '\n';
    return *this;
  }
  Groups& point(int code, const Eigen::Vector2d& p) { return (*this)(code, p.x())(code + 10, p.y())(code + 20, 0.0); }

 private:
  std::ostream& out_;
};

std::string layer_of(int patch) { return "PATCH_" + std::to_string(patch); }
std::string notch_layer_of(int patch) { return layer_of(patch) + "_NOTCHES"; }

void header(Groups& g, const Eigen::AlignedBox2d& bounds) {
  g(0, "SECTION")(2, "HEADER")(9, "$ACADVER")(1, "AC1009");
  g(9, "$EXTMIN").point(10, bounds.min())(9, "$EXTMAX").point(10, bounds.max());
  g(0, "ENDSEC");
}

void tables(Groups& g, const std::set<int>& patches) {
  g(0, "SECTION")(2, "TABLES");
  g(0, "TABLE")(2, "LTYPE")(70, 1);
  g(0, "LTYPE")(2, "CONTINUOUS")(70, 0)(3, "Solid line")(72, 65)(73, 0)(40, 0.0);
  g(0, "ENDTAB");
  g(0, "TABLE")(2, "LAYER")(70, static_cast<int>(2 * patches.size()));
  int colour = 0;
  for (const int patch : patches) {
    for (const std::string& name : {layer_of(patch), notch_layer_of(patch)})
      g(0, "LAYER")(2, name)(70, 0)(62, 1 + colour % 7)(6, "CONTINUOUS");
    ++colour;
  }
  g(0, "ENDTAB")(0, "ENDSEC");
}

void piece_entities(Groups& g, const PatternPiece& piece, double notch, double text) {
  const std::string layer = layer_of(piece.patch);
  for (const auto& outline : piece.outlines) {
    g(0, "POLYLINE")(8, layer)(66, 1).point(10, Eigen::Vector2d::Zero())(70, 1);
    for (const Eigen::Vector2d& p : outline) g(0, "VERTEX")(8, layer).point(10, p);
    g(0, "SEQEND")(8, layer);
  }
  for (const Notch& n : piece.notches)
    g(0, "LINE")(8, notch_layer_of(piece.patch)).point(10, n.at).point(11, n.at + notch * n.inward);
  g(0, "TEXT")(8, layer).point(10, piece.label_at)(40, text)(1, piece.label)(72, 1)(73, 2).point(11, piece.label_at);
}

}  // namespace

void write_dxf(std::ostream& out, const Pattern& pattern) {
  const std::locale previous = out.imbue(std::locale::classic());
  const auto precision = out.precision(10);
  Groups g(out);
  std::set<int> patches;
  for (const PatternPiece& piece : pattern.pieces) patches.insert(piece.patch);
  const Eigen::AlignedBox2d bounds =
      pattern.bounds.isEmpty() ? Eigen::AlignedBox2d(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()) : pattern.bounds;
  const double side = bounds.sizes().maxCoeff();
  header(g, bounds);
  tables(g, patches);
  g(0, "SECTION")(2, "ENTITIES");
  for (const PatternPiece& piece : pattern.pieces) piece_entities(g, piece, kNotch * side, kText * side);
  g(0, "ENDSEC")(0, "EOF");
  out.precision(precision);
  out.imbue(previous);
}

}  // namespace qd
