// Regions of the input that patches never cross: faces with the same existing patch id and the
// same selection state share a region.
#pragma once

#include <vector>

namespace qd::segment {

// One dense label per face (0, 1, … in order of first appearance), or empty when neither patch
// ids nor a selection are given (one region).
std::vector<int> region_labels(const std::vector<int>& patch, const std::vector<char>& selected);

}  // namespace qd::segment
