// Breadth-first search over the face graph, in face order: linear time.
#include "segment/face_parts.h"

namespace qd::segment {

FaceParts connected_parts(const FaceGraph& graph, const std::vector<int>& label) {
  FaceParts parts;
  parts.part.assign(label.size(), -1);
  std::vector<int> queue;
  queue.reserve(label.size());
  for (size_t start = 0; start < label.size(); ++start) {
    if (parts.part[start] >= 0) continue;
    queue.assign(1, static_cast<int>(start));
    parts.part[start] = parts.count;
    for (size_t next = 0; next < queue.size(); ++next)
      for (const int h : graph.neighbour[queue[next]])
        if (h >= 0 && parts.part[h] < 0 && label[h] == label[start]) {
          parts.part[h] = parts.count;
          queue.push_back(h);
        }
    ++parts.count;
  }
  return parts;
}

}  // namespace qd::segment
