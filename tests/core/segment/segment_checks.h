// Checks every segmentation must pass, computed independently of the engine's own bookkeeping.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "segment/segment.h"

namespace qd::test {

using namespace qd::common;
using namespace qd::segment;

// Faces of one patch connected through shared edges (two faces with two common vertices).
inline bool edge_connected(const Triangles& F, const std::vector<int>& faces) {
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;
  for (const int f : faces)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  std::set<int> seen = {faces.front()};
  std::vector<int> stack = {faces.front()};
  while (!stack.empty()) {
    const int f = stack.back();
    stack.pop_back();
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      for (const int h : edge_faces[{std::min(a, b), std::max(a, b)}])
        if (seen.insert(h).second) stack.push_back(h);
    }
  }
  return seen.size() == faces.size();
}

// Every face in exactly one patch 0 … k−1, every patch edge-connected, the report's face counts
// and largest errors true of the reported cones, and every patch within the limit unless the
// report says why not.
inline void expect_valid(const SegmentProblem& p, const SegmentResult& r) {
  ASSERT_EQ(r.patch.size(), static_cast<size_t>(p.F.rows()));
  const int k = static_cast<int>(r.patches.size());
  std::vector<std::vector<int>> faces(static_cast<size_t>(k));
  for (size_t f = 0; f < r.patch.size(); ++f) {
    ASSERT_GE(r.patch[f], 0);
    ASSERT_LT(r.patch[f], k);
    faces[r.patch[f]].push_back(static_cast<int>(f));
  }
  for (int id = 0; id < k; ++id) {
    ASSERT_FALSE(faces[id].empty()) << "patch " << id << " has no face";
    EXPECT_TRUE(edge_connected(p.F, faces[id])) << "patch " << id;
    const SegmentPatch& s = r.patches[id];
    EXPECT_EQ(s.faces, static_cast<int>(faces[id].size()));
    double worst = 0;
    for (const int f : faces[id]) {
      const Vec3 n = face_normal(p.V, p.F, f);
      const double angle = std::acos(std::clamp(n.dot(s.proxy.axis), -1.0, 1.0));
      worst = std::max(worst, std::abs(angle - s.proxy.angle) * 180 / M_PI);
    }
    EXPECT_NEAR(worst, s.max_error_deg, 1e-6) << "patch " << id;
    EXPECT_LE(s.rms_error_deg, s.max_error_deg + 1e-9);
    if (s.over_limit == OverLimit::No)
      EXPECT_LE(s.max_error_deg, p.params.max_error_deg + 1e-9) << "patch " << id;
    else
      EXPECT_GT(s.max_error_deg, p.params.max_error_deg) << "patch " << id;
  }
}

// The patches are exactly the tagged pieces (one patch per piece, one piece per patch).
inline void expect_pieces(const SegmentResult& r, const std::vector<int>& piece) {
  std::map<int, std::set<int>> patches_of_piece, pieces_of_patch;
  for (size_t f = 0; f < piece.size(); ++f) {
    patches_of_piece[piece[f]].insert(r.patch[f]);
    pieces_of_patch[r.patch[f]].insert(piece[f]);
  }
  EXPECT_EQ(r.patches.size(), patches_of_piece.size());
  for (const auto& [pc, patches] : patches_of_piece)
    EXPECT_EQ(patches.size(), 1u) << "piece " << pc << " is split";
  for (const auto& [patch, pieces] : pieces_of_patch)
    EXPECT_EQ(pieces.size(), 1u) << "patch " << patch << " spans pieces";
}

// Segments the problem and expects a valid partition into exactly
// its pieces; returns the result for further checks.
inline SegmentResult segment_into_pieces(const std::vector<int>& pieces, SegmentProblem p) {
  const SegmentResult r = segment::segment(p);
  expect_valid(p, r);
  expect_pieces(r, pieces);
  return r;
}

}  // namespace qd::test
