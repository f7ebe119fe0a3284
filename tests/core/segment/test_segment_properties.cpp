// Properties of every segmentation on doubly curved meshes: a valid partition, patches within
// the limit unless the report says why, the same patches for any thread count, a progress call
// per round, and the target patch count met both ways.
#include <gtest/gtest.h>

#include <algorithm>

#include "segment/segment.h"
#include "segment_checks.h"
#include "segment_meshes.h"

namespace qd::test {
namespace {

using namespace qd::common;
using namespace qd::segment;

TEST(SegmentProperties, TorusPartitionsAreValidAtSeveralLimits) {
  for (const double limit : {5.0, 10.0, 20.0, 40.0}) {
    SegmentProblem p = torus(48, 24).problem();
    p.params.max_error_deg = limit;
    const SegmentResult r = segment::segment(p);
    SCOPED_TRACE(limit);
    expect_valid(p, r);
    EXPECT_GT(r.patches.size(), 1u);
  }
}

TEST(SegmentProperties, SameTorusPatchesForAnyThreadCount) {
  SegmentProblem p = torus(64, 32).problem();
  p.params.max_error_deg = 10;
  p.params.threads = 1;
  const SegmentResult one = segment::segment(p);
  for (const int threads : {2, 3, 8}) {
    p.params.threads = threads;
    const SegmentResult r = segment::segment(p);
    EXPECT_EQ(r.patch, one.patch) << threads << " threads";
    ASSERT_EQ(r.patches.size(), one.patches.size());
    for (size_t id = 0; id < r.patches.size(); ++id) {
      EXPECT_EQ(r.patches[id].max_error_deg, one.patches[id].max_error_deg);
      EXPECT_EQ(r.patches[id].proxy.axis, one.patches[id].proxy.axis);
    }
  }
}

// At a 5° limit no 20 faces of the bump fit one cone: its patches are over the limit at about
// the smallest size, or took in such a part, and the report says which; the flat rest fits.
TEST(SegmentProperties, TooCurvedPartsArePatchesOfTheSmallestSizeOverTheLimit) {
  SegmentProblem p = bumped_plane().problem();
  p.params.max_error_deg = 5;
  const SegmentResult r = segment::segment(p);
  expect_valid(p, r);
  int flagged = 0;
  for (size_t id = 0; id < r.patches.size(); ++id) {
    const SegmentPatch& s = r.patches[id];
    if (s.over_limit == OverLimit::No) continue;
    ++flagged;
    ASSERT_TRUE(s.over_limit == OverLimit::SmallestSize || s.over_limit == OverLimit::SmallPart);
    if (s.over_limit == OverLimit::SmallestSize) {
      EXPECT_LT(s.faces, 2 * p.params.min_faces);
    }
    const std::string line = r.log[r.warnings.size() + id];
    EXPECT_NE(line.find("smallest patch size (20 faces)"), std::string::npos) << line;
  }
  EXPECT_GT(flagged, 0);
  EXPECT_GE(r.patches.front().faces, 400);  // the flat rest, where the lowest face is
  EXPECT_EQ(r.patches.front().over_limit, OverLimit::No);
}

TEST(SegmentProperties, SmallestPatchAsAnAreaFraction) {
  SegmentProblem p = torus(48, 24).problem();
  p.params.max_error_deg = 10;
  p.params.min_faces = 1;
  p.params.min_area = 0.05;
  const SegmentResult r = segment::segment(p);
  expect_valid(p, r);
  double total = 0;
  for (const SegmentPatch& s : r.patches) total += s.area;
  for (const SegmentPatch& s : r.patches) EXPECT_GE(s.area, 0.05 * total * (1 - 1e-9));
}

TEST(SegmentProperties, ProgressIsReportedOncePerRoundInOrder) {
  SegmentProblem p = torus(48, 24).problem();
  std::vector<int> percents;
  int rounds = 0;
  const SegmentResult r = segment::segment(p, [&](int percent, const std::string& message) {
    percents.push_back(percent);
    rounds += message.find("round") != std::string::npos;
  });
  EXPECT_EQ(rounds, r.rounds);
  EXPECT_TRUE(std::is_sorted(percents.begin(), percents.end()));
  EXPECT_EQ(percents.front(), 0);
  EXPECT_EQ(percents.back(), 100);
}

TEST(SegmentProperties, TargetCountMergesOverTheLimitAndSaysSo) {
  SegmentProblem p = torus(48, 24).problem();
  p.params.target_patches = 3;
  const SegmentResult r = segment::segment(p);
  expect_valid(p, r);
  EXPECT_EQ(r.patches.size(), 3u);
  for (const SegmentPatch& s : r.patches) {
    if (s.max_error_deg > p.params.max_error_deg) {
      EXPECT_EQ(s.over_limit, OverLimit::TargetCount);
    }
  }
}

TEST(SegmentProperties, TargetCountSplitsWhenTheFitNeedsFewer) {
  const MeshBuilder b = capped_cylinder();
  SegmentProblem p = b.problem();
  p.params.target_patches = 7;
  const SegmentResult r = segment::segment(p);
  expect_valid(p, r);
  EXPECT_EQ(r.patches.size(), 7u);
  for (const SegmentPatch& s : r.patches) EXPECT_EQ(s.over_limit, OverLimit::No);
  std::map<int, std::set<int>> pieces_of_patch;  // still no patch across two pieces
  for (size_t f = 0; f < r.patch.size(); ++f) pieces_of_patch[r.patch[f]].insert(b.pieces()[f]);
  for (const auto& [patch, pieces] : pieces_of_patch) EXPECT_EQ(pieces.size(), 1u);
}

TEST(SegmentProperties, TargetCountOutOfReachIsSaid) {
  SegmentProblem p = book().problem();  // three pages that no merge may join
  p.params.target_patches = 2;
  const SegmentResult r = segment::segment(p);
  expect_valid(p, r);
  EXPECT_EQ(r.patches.size(), 3u);
  bool said = false;
  for (const std::string& line : r.warnings)
    said = said || line.find("not the target 2") != std::string::npos;
  EXPECT_TRUE(said);
}

}  // namespace
}  // namespace qd::test
