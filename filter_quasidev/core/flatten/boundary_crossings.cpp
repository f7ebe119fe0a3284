#include "flatten/boundary_crossings.h"

#include <algorithm>
#include <cmath>

namespace qd::flatten {

namespace {

// Twice the signed area of (a, b, c): > 0 when c lies left of a→b.
double orient(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Proper crossing: each segment's ends lie strictly on both sides of the other's line.
bool cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
           const Eigen::Vector2d& d) {
  return orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0;
}

}  // namespace

std::vector<char> crossing_segments(const Eigen::MatrixX2d& uv,
                                    const std::vector<std::array<int, 2>>& segments) {
  const size_t m = segments.size();
  std::vector<char> crossing(m, 0);
  if (m < 4) return crossing;
  const auto end = [&](size_t s, int k) -> Eigen::Vector2d {
    return uv.row(segments[s][k]).transpose();
  };
  Eigen::Vector2d lo = end(0, 0), hi = lo;
  double total = 0;
  for (size_t s = 0; s < m; ++s) {
    lo = lo.cwiseMin(end(s, 0)).cwiseMin(end(s, 1));
    hi = hi.cwiseMax(end(s, 0)).cwiseMax(end(s, 1));
    total += (end(s, 1) - end(s, 0)).norm();
  }
  // About one segment per cell, at most about m cells.
  const double side = std::max({total / static_cast<double>(m),
                                (hi - lo).maxCoeff() / std::sqrt(static_cast<double>(m)), 1e-300});
  const int nx = static_cast<int>((hi.x() - lo.x()) / side) + 1,
            ny = static_cast<int>((hi.y() - lo.y()) / side) + 1;
  const auto cell = [&](double x, double lo_x, int count) {
    return std::min(count - 1, static_cast<int>((x - lo_x) / side));
  };
  std::vector<std::vector<int>> in_cell(static_cast<size_t>(nx) * static_cast<size_t>(ny));
  for (size_t s = 0; s < m; ++s) {
    const Eigen::Vector2d a = end(s, 0).cwiseMin(end(s, 1)), b = end(s, 0).cwiseMax(end(s, 1));
    for (int i = cell(a.x(), lo.x(), nx); i <= cell(b.x(), lo.x(), nx); ++i)
      for (int j = cell(a.y(), lo.y(), ny); j <= cell(b.y(), lo.y(), ny); ++j)
        in_cell[static_cast<size_t>(j) * static_cast<size_t>(nx) + static_cast<size_t>(i)]
            .push_back(static_cast<int>(s));
  }
  for (const std::vector<int>& here : in_cell)
    for (size_t x = 0; x < here.size(); ++x)
      for (size_t y = x + 1; y < here.size(); ++y) {
        const auto& p = segments[here[x]];
        const auto& q = segments[here[y]];
        if (p[0] == q[0] || p[0] == q[1] || p[1] == q[0] || p[1] == q[1]) continue;
        if (!cross(end(here[x], 0), end(here[x], 1), end(here[y], 0), end(here[y], 1))) continue;
        crossing[here[x]] = crossing[here[y]] = 1;
      }
  return crossing;
}

}  // namespace qd::flatten
