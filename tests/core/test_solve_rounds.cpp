// Rounds of solve groups: groups in one round move no common vertex, neighbours run one after
// the other, and the schedule is the same whatever the thread count (it does not take one).
#include <gtest/gtest.h>

#include <set>

#include "approximate/solve_rounds.h"
#include "test_meshes.h"

namespace qd {
namespace {

using namespace qd::approximate;
using namespace qd::common;

std::vector<std::vector<int>> groups_by_patch(const Problem& p, int patches) {
  std::vector<std::vector<int>> groups(static_cast<size_t>(patches));
  for (size_t f = 0; f < p.patch.size(); ++f)
    groups[static_cast<size_t>(p.patch[f])].push_back(static_cast<int>(f));
  return groups;
}

TEST(SolveRounds, NeighbouringGroupsNeverShareARound) {
  const Problem p = test::bumpy_cylinder(24, 6, 0.0, 0.0, 6);  // a ring of 6 sectors
  const auto groups = groups_by_patch(p, 6);
  const auto rounds =
      solve_rounds(groups, p.F, std::vector<char>(static_cast<size_t>(p.V.rows()), 0));
  std::set<size_t> all;
  for (const auto& round : rounds) {
    std::set<int> used;
    for (size_t g : round) {
      EXPECT_TRUE(all.insert(g).second) << "group " << g << " scheduled twice";
      std::set<int> mine;
      for (int f : groups[g])
        for (int c = 0; c < 3; ++c) mine.insert(p.F(f, c));
      for (int v : mine)
        EXPECT_TRUE(used.insert(v).second) << "vertex " << v << " in two groups of a round";
    }
  }
  EXPECT_EQ(all.size(), 6u);
  // A ring of 6 is 2-colourable: sectors 0, 2, 4 first, then 1, 3, 5.
  ASSERT_EQ(rounds.size(), 2u);
  EXPECT_EQ(rounds[0], (std::vector<size_t>{0, 2, 4}));
  EXPECT_EQ(rounds[1], (std::vector<size_t>{1, 3, 5}));
}

// With the seams held (every pass of fixed seams), the sectors move no common vertex: one round.
TEST(SolveRounds, GroupsSharingOnlyHeldVerticesShareARound) {
  const Problem p = test::bumpy_cylinder(24, 6, 0.0, 0.0, 6);
  std::vector<char> held(static_cast<size_t>(p.V.rows()), 0);
  for (Eigen::Index v = 0; v < p.V.rows(); ++v)
    held[static_cast<size_t>(v)] = v % 24 % 4 == 0;  // sector borders
  const auto rounds = solve_rounds(groups_by_patch(p, 6), p.F, held);
  ASSERT_EQ(rounds.size(), 1u);
  EXPECT_EQ(rounds[0], (std::vector<size_t>{0, 1, 2, 3, 4, 5}));
}

TEST(SolveRounds, SeparateGroupsShareOneRound) {
  Problem a = test::bumpy_cylinder(12, 3, 0.0);
  const Eigen::Index n = a.V.rows();
  Triangles F(2 * a.F.rows(), 3);
  F << a.F, (a.F.array() + static_cast<int>(n)).matrix();  // a second, disjoint copy
  std::vector<std::vector<int>> groups(2);
  for (int f = 0; f < F.rows(); ++f) groups[f < a.F.rows() ? 0 : 1].push_back(f);
  const auto rounds = solve_rounds(groups, F, std::vector<char>(static_cast<size_t>(2 * n), 0));
  ASSERT_EQ(rounds.size(), 1u);
  EXPECT_EQ(rounds[0], (std::vector<size_t>{0, 1}));
}

}  // namespace
}  // namespace qd
