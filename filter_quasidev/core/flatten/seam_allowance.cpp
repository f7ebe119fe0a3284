#include "flatten/seam_allowance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <polyclipping/clipper.hpp>

namespace qd::flatten {

namespace {

// Clipper works on integers. The piece is centred and scaled so that its extent (allowance
// and miter spikes included) spans ±2^30, Clipper's range for plain 64-bit arithmetic: the
// rounding is then a billionth of the piece's size whatever the model's unit (mm or metres).
constexpr double kIntegerRange = 1073741824.0;

// 2D cross product.
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// The nearest crossing of the ray from `at` along `outward` with the cut lines; `at` if none.
Eigen::Vector2d ray_exit(const Eigen::Vector2d& at, const Eigen::Vector2d& outward,
                         const std::vector<Outline>& cut) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const Outline& loop : cut)
    for (size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector2d& a = loop[i];
      const Eigen::Vector2d edge = loop[(i + 1) % loop.size()] - a;
      const double denominator = cross(outward, edge);
      if (denominator == 0) continue;                         // parallel
      const double t = cross(a - at, edge) / denominator;     // along the ray
      const double s = cross(a - at, outward) / denominator;  // along the edge
      if (t > 0 && s >= 0 && s <= 1) nearest = std::min(nearest, t);
    }
  return std::isfinite(nearest) ? Eigen::Vector2d(at + nearest * outward) : at;
}

}  // namespace

std::vector<Outline> cut_lines(const std::vector<Outline>& sew_lines, double allowance) {
  if (allowance <= 0) return sew_lines;
  Eigen::AlignedBox2d box;
  for (const Outline& loop : sew_lines)
    for (const Eigen::Vector2d& p : loop) box.extend(p);
  if (box.isEmpty()) return sew_lines;
  const Eigen::Vector2d centre = box.center();
  const double scale = kIntegerRange / (box.sizes().maxCoeff() / 2 + kAllowanceReach * allowance);

  ClipperLib::Paths paths;
  for (const Outline& loop : sew_lines) {
    ClipperLib::Path path;
    for (const Eigen::Vector2d& p : loop) {
      const Eigen::Vector2d q = (p - centre) * scale;
      path.emplace_back(std::llround(q.x()), std::llround(q.y()));
    }
    paths.push_back(std::move(path));
  }
  // Non-zero filling: holes run opposite to their outer loop whichever way the piece turns,
  // and a boundary that overlaps itself is cut as one region.
  ClipperLib::SimplifyPolygons(paths, ClipperLib::pftNonZero);
  ClipperLib::ClipperOffset offset(kAllowanceReach);  // the miter limit: farther spikes squared off
  offset.AddPaths(paths, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  ClipperLib::PolyTree tree;
  offset.Execute(tree, allowance * scale);

  std::vector<Outline> cut;
  for (const ClipperLib::PolyNode* node = tree.GetFirst(); node; node = node->GetNext()) {
    Outline loop;
    for (const ClipperLib::IntPoint& q : node->Contour)
      loop.push_back(centre +
                     Eigen::Vector2d(static_cast<double>(q.X), static_cast<double>(q.Y)) / scale);
    if (ClipperLib::Orientation(node->Contour) == node->IsHole())  // true: counter-clockwise
      std::reverse(loop.begin(), loop.end());
    cut.push_back(std::move(loop));
  }
  return cut;
}

void add_seam_allowance(PatternPiece& piece, double allowance) {
  piece.cut_outlines = cut_lines(piece.outlines, allowance);
  for (Notch& notch : piece.notches)
    notch.cut_at = allowance > 0 ? ray_exit(notch.at, -notch.inward, piece.cut_outlines) : notch.at;
}

}  // namespace qd::flatten
