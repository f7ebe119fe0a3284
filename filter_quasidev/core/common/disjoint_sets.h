// Union-find over 0..n−1 with path halving (Tarjan 1975). The representative of a set is
// whichever element the joins left on top: callers that need a deterministic numbering number
// the sets by their first element in index order, never by representative.
#pragma once

#include <numeric>
#include <vector>

namespace qd::common {

class DisjointSets {
 public:
  explicit DisjointSets(size_t count) : parent_(count) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int find(int x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  // Joins the sets of a and b; false when they were one set already.
  bool join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[a] = b;
    return true;
  }
  // Set number per element: 0, 1, … in the order of each set's first element.
  std::vector<int> numbering(int* sets = nullptr) {
    std::vector<int> number_of_root(parent_.size(), -1), number(parent_.size());
    int next = 0;
    for (size_t x = 0; x < parent_.size(); ++x) {
      int& n = number_of_root[static_cast<size_t>(find(static_cast<int>(x)))];
      if (n < 0) n = next++;
      number[x] = n;
    }
    if (sets) *sets = next;
    return number;
  }

 private:
  std::vector<int> parent_;
};

}  // namespace qd::common
