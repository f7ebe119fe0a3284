// Area and length of outlines: a square with a square hole, against their sums by hand.
#include <gtest/gtest.h>

#include "flatten/outline_measures.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

const qd::flatten::Outline kSquare = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};  // area 16, length 16
const qd::flatten::Outline kHole = {{1, 1}, {1, 2}, {2, 2}, {2, 1}};  // clockwise, area 1, length 4

TEST(OutlineMeasures, SignedAreaFollowsTheTurn) {
  EXPECT_NEAR(qd::flatten::loop_area(kSquare), 16, 1e-12);
  EXPECT_NEAR(qd::flatten::loop_area(kHole), -1, 1e-12);
}

TEST(OutlineMeasures, OuterLoopLessHolesAndEveryLoopsLength) {
  const std::vector<qd::flatten::Outline> piece = {kHole,
                                                   kSquare};  // the outer loop need not come first
  EXPECT_EQ(qd::flatten::outer_loop(piece), 1u);
  EXPECT_NEAR(qd::flatten::outline_area(piece), 15, 1e-12);
  EXPECT_NEAR(qd::flatten::outline_length(piece), 20, 1e-12);
  EXPECT_EQ(qd::flatten::outline_area({}), 0);
  EXPECT_EQ(qd::flatten::outline_length({}), 0);
}

}  // namespace
