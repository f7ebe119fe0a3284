#include "approximate/solve_rounds.h"

#include <algorithm>
#include <cassert>

namespace qd::approximate {

std::vector<std::vector<size_t>> solve_rounds(const std::vector<std::vector<int>>& groups,
                                              const Triangles& F, const std::vector<char>& held) {
  // Groups touching each moving vertex, then each group's neighbours.
  std::vector<std::vector<size_t>> at_vertex(held.size());
  for (size_t g = 0; g < groups.size(); ++g)
    for (int f : groups[g])
      for (int c = 0; c < 3; ++c) {
        const auto v = static_cast<size_t>(F(f, c));
        if (held[v]) continue;
        std::vector<size_t>& list = at_vertex[v];
        if (list.empty() || list.back() != g) list.push_back(g);
      }
  std::vector<std::vector<size_t>> neighbours(groups.size());
  for (const std::vector<size_t>& list : at_vertex)
    for (size_t a : list)
      for (size_t b : list)
        if (a != b) neighbours[a].push_back(b);

  std::vector<int> round_of(groups.size(), -1);
  std::vector<std::vector<size_t>> rounds;
  for (size_t g = 0; g < groups.size(); ++g) {
    std::vector<char> taken(rounds.size() + 1, 0);
    for (size_t n : neighbours[g])
      if (round_of[n] >= 0) taken[static_cast<size_t>(round_of[n])] = 1;
    const size_t r = static_cast<size_t>(std::find(taken.begin(), taken.end(), 0) - taken.begin());
    if (r == rounds.size()) rounds.emplace_back();
    rounds[r].push_back(g);
    round_of[g] = static_cast<int>(r);
  }
  // Groups of one round share no moving vertex: they run in parallel on one position array.
  assert(std::all_of(at_vertex.begin(), at_vertex.end(), [&](const std::vector<size_t>& list) {
    return std::all_of(list.begin(), list.end(), [&](size_t a) {
      return std::count_if(list.begin(), list.end(),
                           [&](size_t b) { return round_of[a] == round_of[b]; }) == 1;
    });
  }));
  return rounds;
}

}  // namespace qd::approximate
