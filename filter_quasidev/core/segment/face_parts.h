// Edge-connected parts of a face labelling: two faces neighbouring in the face graph with the
// same label are in the same part.
#pragma once

#include <vector>

#include "segment/face_graph.h"

namespace qd::segment {

struct FaceParts {
  std::vector<int> part;  // per face, numbered in the order of each part's lowest face
  int count = 0;
};

FaceParts connected_parts(const FaceGraph& graph, const std::vector<int>& label);

}  // namespace qd::segment
