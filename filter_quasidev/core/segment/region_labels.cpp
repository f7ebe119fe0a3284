// Dense region labels from (patch id, selected) pairs.
#include "segment/region_labels.h"

#include <cstddef>
#include <map>
#include <utility>

namespace qd::segment {

std::vector<int> region_labels(const std::vector<int>& patch, const std::vector<char>& selected) {
  const std::size_t n = patch.empty() ? selected.size() : patch.size();
  std::vector<int> label(n);
  std::map<std::pair<int, bool>, int> dense;
  for (std::size_t f = 0; f < n; ++f) {
    const std::pair<int, bool> key(patch.empty() ? 0 : patch[f],
                                   !selected.empty() && selected[f] != 0);
    label[f] = dense.emplace(key, static_cast<int>(dense.size())).first->second;
  }
  return label;
}

}  // namespace qd::segment
