// Multi-source breadth-first search from the faces on a border, and a linear scan for the seeds.
#include "segment/chart_seeds.h"

#include <tuple>

namespace qd::segment {

std::vector<int> hops_to_border(const FaceGraph& graph, const std::vector<int>& label,
                                const std::vector<int>& faces) {
  std::vector<int> hops(label.size(), kNoBorder);
  std::vector<int> queue;
  queue.reserve(faces.size());
  for (const int f : faces)
    for (const int h : graph.neighbour[f])
      if (h < 0 || label[h] != label[f]) {
        hops[f] = 0;
        queue.push_back(f);
        break;
      }
  for (size_t next = 0; next < queue.size(); ++next) {
    const int f = queue[next];
    for (const int h : graph.neighbour[f])
      if (h >= 0 && hops[h] == kNoBorder) {  // a neighbour has f's label, or f were a source
        hops[h] = hops[f] + 1;
        queue.push_back(h);
      }
  }
  return hops;
}

std::vector<int> interior_faces(const std::vector<int>& hops, const std::vector<int>& label,
                                int count, const std::vector<double>& deviation, double limit) {
  std::vector<int> best(static_cast<size_t>(count), -1);
  for (size_t i = 0; i < label.size(); ++i) {
    const int c = label[i], f = static_cast<int>(i);
    const double d = deviation.empty() ? 0.0 : deviation[i];
    if (c < 0 || d > limit) continue;
    const int b = best[c];
    if (b < 0 || std::make_tuple(-hops[i], d) <
                     std::make_tuple(-hops[b], deviation.empty() ? 0.0 : deviation[b]))
      best[c] = f;
  }
  return best;
}

}  // namespace qd::segment
