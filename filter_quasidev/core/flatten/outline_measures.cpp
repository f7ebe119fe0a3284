#include "flatten/outline_measures.h"

#include <cmath>

namespace qd::flatten {

double loop_area(const Outline& loop) {
  double twice = 0;
  for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
    const Eigen::Vector2d& a = loop[i];
    const Eigen::Vector2d& b = loop[(i + 1) % n];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return twice / 2;
}

std::size_t outer_loop(const std::vector<Outline>& loops) {
  std::size_t outer = 0;
  for (std::size_t i = 1; i < loops.size(); ++i)
    if (std::abs(loop_area(loops[i])) > std::abs(loop_area(loops[outer]))) outer = i;
  return outer;
}

double outline_area(const std::vector<Outline>& loops) {
  if (loops.empty()) return 0;
  const std::size_t outer = outer_loop(loops);
  double area = std::abs(loop_area(loops[outer]));
  for (std::size_t i = 0; i < loops.size(); ++i)
    if (i != outer) area -= std::abs(loop_area(loops[i]));
  return area;
}

double outline_length(const std::vector<Outline>& loops) {
  double length = 0;
  for (const Outline& loop : loops)
    for (std::size_t i = 0, n = loop.size(); i < n; ++i)
      length += (loop[(i + 1) % n] - loop[i]).norm();
  return length;
}

Eigen::AlignedBox2d loop_box(const Outline& loop) {
  Eigen::AlignedBox2d box;
  for (const Eigen::Vector2d& p : loop) box.extend(p);
  return box;
}

Eigen::AlignedBox2d outline_box(const std::vector<Outline>& loops) {
  Eigen::AlignedBox2d box;
  for (const Outline& loop : loops) box.extend(loop_box(loop));
  return box;
}

}  // namespace qd::flatten
