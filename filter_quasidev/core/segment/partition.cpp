// Bucketing faces by chart.
#include "segment/partition.h"

#include <algorithm>
#include <cassert>

namespace qd::segment {

std::vector<std::vector<int>> faces_by_chart(const std::vector<int>& label, int count) {
  assert(std::all_of(label.begin(), label.end(), [&](int l) { return l < count; }));
  std::vector<std::vector<int>> faces(static_cast<size_t>(count));
  for (size_t f = 0; f < label.size(); ++f)
    if (label[f] >= 0) faces[label[f]].push_back(static_cast<int>(f));
  return faces;
}

std::vector<int> faces_labelled(const std::vector<int>& label, int value) {
  std::vector<int> faces;
  for (size_t f = 0; f < label.size(); ++f)
    if (label[f] == value) faces.push_back(static_cast<int>(f));
  return faces;
}

double faces_area(const FaceGeometry& g, const std::vector<int>& faces) {
  double area = 0;
  for (const int f : faces) area += g.area[f];
  return area;
}

}  // namespace qd::segment
