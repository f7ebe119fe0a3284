#include "flatten/pattern_sheet.h"

#include <algorithm>

#include "flatten/layout.h"
#include "flatten/outline_measures.h"

namespace qd::flatten {

namespace {

void move(PatternPiece& p, const Eigen::Vector2d& by) {
  for (std::vector<Outline>* lines : {&p.outlines, &p.cut_outlines})
    for (Outline& outline : *lines)
      for (Eigen::Vector2d& at : outline) at += by;
  for (Notch& n : p.notches) {
    n.at += by;
    n.cut_at += by;
  }
  p.label_at += by;
}

}  // namespace

Pattern pattern_sheet(std::vector<PatternPiece> pieces, const std::vector<PieceGroup>& groups,
                      double gap) {
  std::vector<PatternPiece> cut;
  std::vector<Eigen::AlignedBox2d> boxes;
  for (const PieceGroup& g : groups) {
    PatternPiece p = std::move(pieces[static_cast<size_t>(g.members.front())]);
    p.quantity = static_cast<int>(g.members.size());
    p.mirrored = static_cast<int>(std::count(g.mirrored.begin(), g.mirrored.end(), 1));
    boxes.push_back(outline_box(p.cut_outlines));
    cut.push_back(std::move(p));
  }
  const std::vector<Eigen::Vector2d> corner = shelf_pack(boxes, gap);
  for (size_t i = 0; i < cut.size(); ++i) move(cut[i], corner[i] - boxes[i].min());
  return make_pattern(std::move(cut));
}

}  // namespace qd::flatten
