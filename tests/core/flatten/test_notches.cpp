// Notches: the same mesh vertices on both sides of a seam, at its ends and every `spacing`.
#include <gtest/gtest.h>

#include "flatten/notches.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

// Vertices 0..10 on the x axis, 1 apart; 11..22 on a circle of circumference ≈ 12.
qd::common::Positions points() {
  qd::common::Positions V(23, 3);
  for (int i = 0; i <= 10; ++i) V.row(i) << i, 0, 0;
  const double r = 12 / (2 * M_PI);
  for (int i = 0; i < 12; ++i)
    V.row(11 + i) << r * std::cos(2 * M_PI * i / 12), r * std::sin(2 * M_PI * i / 12), 5;
  return V;
}

std::vector<int> notched(const std::vector<char>& flags) {
  std::vector<int> v;
  for (size_t i = 0; i < flags.size(); ++i)
    if (flags[i]) v.push_back(static_cast<int>(i));
  return v;
}

TEST(Notches, OpenSeamGetsItsEndsAndEveryTwoUnits) {
  std::vector<std::array<int, 2>> edges;
  for (int i = 0; i < 10; ++i) {
    edges.push_back({i, i + 1});  // one side
    edges.push_back({i + 1, i});  // the other side, running the other way
  }
  edges.push_back({3, 15});  // a boundary edge of one piece only: no seam
  EXPECT_EQ(notched(qd::flatten::notch_vertices(points(), edges, 2.0)),
            (std::vector<int>{0, 2, 4, 6, 8, 10}));
}

TEST(Notches, ClosedSeamStartsAtItsLowestVertex) {
  std::vector<std::array<int, 2>> edges;
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < 12; ++i) edges.push_back({11 + (i + 5) % 12, 11 + (i + 6) % 12});
  EXPECT_EQ(notched(qd::flatten::notch_vertices(points(), edges, 3.0)),
            (std::vector<int>{11, 14, 17, 20}));
}

TEST(Notches, JunctionsAreNotchedWhateverTheSpacing) {
  // A T: 0–5 along x and 5–16 (a detour through the circle vertex 16), each seam listed twice.
  std::vector<std::array<int, 2>> edges;
  for (int side = 0; side < 2; ++side) {
    for (int i = 0; i < 10; ++i) edges.push_back({i, i + 1});
    edges.push_back({5, 16});
  }
  const std::vector<int> n = notched(qd::flatten::notch_vertices(points(), edges, 100.0));
  EXPECT_EQ(n, (std::vector<int>{0, 5, 10, 16}));
}

}  // namespace
