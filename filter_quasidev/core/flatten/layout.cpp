#include "flatten/layout.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>

namespace qd::flatten {

namespace {

constexpr double kAutoGap = 0.05;    // of the largest piece's longer side
constexpr double kShelfWidth = 1.5;  // of √(total box area)

Eigen::AlignedBox2d box_of(const Eigen::MatrixX2d& points) {
  return Eigen::AlignedBox2d(points.colwise().minCoeff().transpose(),
                             points.colwise().maxCoeff().transpose());
}

[[maybe_unused]] constexpr size_t kCheckedPieces = 1000;

// No two boxes placed at their corners overlap (they may touch).
[[maybe_unused]] bool apart(const std::vector<Eigen::AlignedBox2d>& boxes,
                            const std::vector<Eigen::Vector2d>& corner) {
  for (size_t i = 0; i < boxes.size(); ++i)
    for (size_t j = 0; j < i; ++j) {
      const Eigen::Vector2d lo = corner[i].cwiseMax(corner[j]);
      const Eigen::Vector2d hi =
          (corner[i] + boxes[i].sizes()).cwiseMin(corner[j] + boxes[j].sizes());
      if ((hi - lo).minCoeff() > 0) return false;
    }
  return true;
}

}  // namespace

Eigen::Matrix2d grain_rotation(const Eigen::Vector2d& grain) {
  Eigen::Matrix2d R;
  R << grain.y(), -grain.x(), grain.x(), grain.y();
  return R;
}

std::vector<Eigen::Vector2d> shelf_pack(const std::vector<Eigen::AlignedBox2d>& boxes, double gap) {
  std::vector<size_t> order(boxes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return boxes[a].sizes().y() > boxes[b].sizes().y(); });
  double area = 0, widest = 0;
  for (const Eigen::AlignedBox2d& b : boxes) {
    area += (b.sizes().x() + gap) * (b.sizes().y() + gap);
    widest = std::max(widest, b.sizes().x());
  }
  const double width = std::max(widest, kShelfWidth * std::sqrt(area));
  std::vector<Eigen::Vector2d> corner(boxes.size());
  double x = 0, y = 0, shelf_height = 0;
  for (const size_t i : order) {
    const Eigen::Vector2d size = boxes[i].sizes();
    if (x > 0 && x + size.x() > width) {  // next shelf
      y += shelf_height + gap;
      x = shelf_height = 0;
    }
    corner[i] = Eigen::Vector2d(x, y);
    x += size.x() + gap;
    shelf_height = std::max(shelf_height, size.y());
  }
  // The check is quadratic: made up to kCheckedPieces pieces (patterns of one-triangle patches
  // can have 100,000).
  assert(boxes.size() > kCheckedPieces || apart(boxes, corner));
  return corner;
}

double sheet_gap(const std::vector<Eigen::AlignedBox2d>& boxes, double gap) {
  if (gap > 0) return gap;
  double longest = 0;
  for (const Eigen::AlignedBox2d& box : boxes) longest = std::max(longest, box.sizes().maxCoeff());
  return kAutoGap * longest;
}

std::vector<Eigen::AlignedBox2d> lay_out(std::vector<Eigen::MatrixX2d>& pieces,
                                         const std::vector<Eigen::Vector2d>& grain, double gap,
                                         double margin) {
  assert(grain.size() == pieces.size());
  std::vector<Eigen::AlignedBox2d> boxes, grown;
  for (size_t i = 0; i < pieces.size(); ++i) {
    Eigen::MatrixX2d& uv = pieces[i];
    uv = uv * grain_rotation(grain[i]).transpose();
    boxes.push_back(box_of(uv));
    grown.emplace_back(boxes.back().min().array() - margin, boxes.back().max().array() + margin);
  }
  const std::vector<Eigen::Vector2d> corner = shelf_pack(grown, sheet_gap(boxes, gap));
  for (size_t i = 0; i < pieces.size(); ++i) {
    pieces[i].rowwise() += (corner[i] - grown[i].min()).transpose();
    boxes[i] = box_of(pieces[i]);
  }
  return boxes;
}

}  // namespace qd::flatten
