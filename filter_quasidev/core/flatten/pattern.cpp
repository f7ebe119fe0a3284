#include "flatten/pattern.h"

#include "flatten/outline_measures.h"

namespace qd::flatten {

namespace {

// Left normal of a→b (into the piece, as the outline runs counter-clockwise), unit or zero.
Eigen::Vector2d left_normal(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  return Eigen::Vector2d(-d.y(), d.x()).normalized();
}

Eigen::Vector2d area_centroid(const Triangles& F, const Eigen::MatrixX2d& uv) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double area = 0;
  for (int f = 0; f < F.rows(); ++f) {
    const Eigen::Vector2d a = uv.row(F(f, 0)), b = uv.row(F(f, 1)), c = uv.row(F(f, 2));
    const Eigen::Vector2d ab = b - a, ac = c - a;
    const double doubled = ab.x() * ac.y() - ab.y() * ac.x();
    sum += doubled * (a + b + c) / 3;
    area += doubled;
  }
  return area != 0 ? Eigen::Vector2d(sum / area) : Eigen::Vector2d(uv.colwise().mean().transpose());
}

}  // namespace

PatternPiece pattern_piece(int patch, const std::string& label, const Triangles& F,
                           const Eigen::MatrixX2d& uv, const std::vector<std::vector<int>>& loops,
                           const std::vector<char>& notch) {
  PatternPiece p;
  p.patch = patch;
  p.label = label;
  p.label_at = area_centroid(F, uv);
  for (const std::vector<int>& loop : loops) {
    std::vector<Eigen::Vector2d> outline;
    const size_t m = loop.size();
    for (size_t i = 0; i < m; ++i) {
      const Eigen::Vector2d prev = uv.row(loop[(i + m - 1) % m]), at = uv.row(loop[i]),
                            next = uv.row(loop[(i + 1) % m]);
      outline.push_back(at);
      if (!notch[loop[i]]) continue;
      const Eigen::Vector2d sum = left_normal(prev, at) + left_normal(at, next);
      p.notches.push_back(
          {at, sum.norm() > 1e-12 ? Eigen::Vector2d(sum.normalized()) : left_normal(at, next), at});
    }
    p.outlines.push_back(std::move(outline));
  }
  p.cut_outlines = p.outlines;
  return p;
}

Pattern make_pattern(std::vector<PatternPiece> pieces) {
  Pattern pattern;
  pattern.pieces = std::move(pieces);
  for (const PatternPiece& p : pattern.pieces)
    pattern.bounds.extend(outline_box(p.outlines)).extend(outline_box(p.cut_outlines));
  return pattern;
}

}  // namespace qd::flatten
