// validate(): one test per kind of bad input (the message must name the key fact) and
// odd-but-workable inputs that must pass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "approximate/validate.h"
#include "common/error.h"

namespace {

using namespace qd::approximate;
using namespace qd::common;

// n×n grid of vertices in the plane z = 0 (index = n·row + column), two faces per quad.
qd::approximate::Problem grid(int n) {
  qd::approximate::Problem p;
  p.V.resize(n * n, 3);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) p.V.row(n * r + c) << c, r, 0;
  p.F.resize(2 * (n - 1) * (n - 1), 3);
  int f = 0;
  for (int r = 0; r + 1 < n; ++r) {
    for (int c = 0; c + 1 < n; ++c) {
      const int a = n * r + c;
      p.F.row(f++) << a, a + 1, a + n + 1;
      p.F.row(f++) << a, a + n + 1, a + n;
    }
  }
  p.params.tolerance = 0.1;
  return p;
}

// 4×4 grid: the left quad column (6 faces) is patch 0, the rest (12 faces) patch 1.
// Seam vertices 1, 5, 9, 13; interior vertices 6 and 10 stay free.
qd::approximate::Problem two_patches() {
  qd::approximate::Problem p = grid(4);
  for (int f = 0; f < p.F.rows(); ++f) p.patch.push_back((f / 2) % 3 == 0 ? 0 : 1);
  return p;
}

void append_vertex(qd::approximate::Problem& p, double x, double y, double z) {
  p.V.conservativeResize(p.V.rows() + 1, 3);
  p.V.row(p.V.rows() - 1) << x, y, z;
}

void append_face(qd::approximate::Problem& p, int a, int b, int c, int patch_id) {
  p.F.conservativeResize(p.F.rows() + 1, 3);
  p.F.row(p.F.rows() - 1) << a, b, c;
  if (!p.patch.empty()) p.patch.push_back(patch_id);
}

// The qd::common::Error message of validate(p), or "" when it passes.
std::string message(const qd::approximate::Problem& p) {
  try {
    qd::approximate::validate(p);
  } catch (const qd::common::Error& e) {
    return e.what();
  }
  return "";
}

bool mentions(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

TEST(Validate, TwoPatchGridPassesAndReturnsTopology) {
  const qd::common::Topology t = qd::approximate::validate(two_patches());
  ASSERT_EQ(t.seam.size(), 16u);
  EXPECT_TRUE(t.seam[5]);
  EXPECT_FALSE(t.seam[6]);
  EXPECT_TRUE(t.boundary[0]);
  EXPECT_FALSE(t.boundary[10]);
}

TEST(Validate, NoVertices) {
  qd::approximate::Problem p;
  p.params.tolerance = 0.1;
  EXPECT_TRUE(mentions(message(p), "no vertices"));
}

TEST(Validate, NoFaces) {
  qd::approximate::Problem p = grid(3);
  p.F.resize(0, 3);
  EXPECT_TRUE(mentions(message(p), "no faces"));
}

TEST(Validate, NonFiniteCoordinates) {
  qd::approximate::Problem p = grid(4);
  p.V(7, 1) = kNaN;
  p.V(12, 0) = kInf;
  const std::string m = message(p);
  EXPECT_TRUE(mentions(m, "2 vertices")) << m;
  EXPECT_TRUE(mentions(m, "vertex 7")) << m;
}

TEST(Validate, FaceIndexOutOfRange) {
  qd::approximate::Problem p = grid(4);
  p.F(3, 1) = 99;
  const std::string m = message(p);
  EXPECT_TRUE(mentions(m, "Face 3")) << m;
  EXPECT_TRUE(mentions(m, "99")) << m;
  p.F(3, 1) = -1;
  EXPECT_TRUE(mentions(message(p), "Face 3"));
}

TEST(Validate, RepeatedIndexInFace) {
  qd::approximate::Problem p = grid(4);
  p.F(5, 2) = p.F(5, 0);
  const std::string m = message(p);
  EXPECT_TRUE(mentions(m, "Face 5")) << m;
  EXPECT_TRUE(mentions(m, "twice")) << m;
}

TEST(Validate, ZeroAreaFace) {
  qd::approximate::Problem p = two_patches();
  append_vertex(p, 0.5, 0, 0);  // on edge 0–1: the new face is flat
  append_face(p, 1, 0, 16, 0);
  const std::string m = message(p);
  EXPECT_TRUE(mentions(m, "1 zero-area face ")) << m;
  EXPECT_TRUE(mentions(m, "face 18")) << m;
  EXPECT_TRUE(mentions(m, "Remove Zero Area Faces")) << m;
}

TEST(Validate, ZeroAreaIsRelativeToEdgeLength) {
  qd::approximate::Problem p = two_patches();
  p.V *= 1e-9;  // tiny model units, same shape
  p.params.tolerance = 1e-10;
  EXPECT_EQ(message(p), "");
}

// Two faces hang below edge 0–1 of patch 0: it is kept, fixed, with a warning.
qd::approximate::Problem with_flaps() {
  qd::approximate::Problem p = two_patches();
  append_vertex(p, 0.5, -1, 1);
  append_face(p, 1, 0, 16, 0);  // edge 0–1 now has a third face below
  append_vertex(p, 0.5, -1, -1);
  append_face(p, 1, 0, 17, 0);
  return p;
}

TEST(Validate, NonManifoldEdgePassesWithAWarning) {
  const qd::common::Topology t = qd::approximate::validate(with_flaps());
  EXPECT_TRUE(t.nonmanifold[0] && t.nonmanifold[1]);
  EXPECT_EQ(std::count(t.nonmanifold.begin(), t.nonmanifold.end(), 1), 2);
  const std::vector<std::string> w = qd::approximate::warnings(t);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_TRUE(mentions(w[0], "1 non-manifold edge ")) << w[0];
  EXPECT_TRUE(mentions(w[0], "first: between vertices 0 and 1")) << w[0];
  EXPECT_TRUE(mentions(w[0], "their 2 vertices are kept fixed")) << w[0];
  EXPECT_TRUE(mentions(w[0], "Repair non Manifold Edges")) << w[0];
}

TEST(Validate, CleanMeshHasNoWarnings) {
  EXPECT_TRUE(qd::approximate::warnings(qd::approximate::validate(two_patches())).empty());
}

TEST(Validate, DuplicateFaces) {
  qd::approximate::Problem p = two_patches();
  append_face(p, 0, 1, 5, 0);  // face 0 again
  append_face(p, 5, 0, 1, 0);  // and again, rotated
  const std::string m = message(p);
  EXPECT_TRUE(mentions(m, "2 duplicate faces (first: faces 0 and 18 ")) << m;
  EXPECT_TRUE(mentions(m, "Remove Duplicate Faces")) << m;
}

TEST(Validate, NothingFreeButNonManifoldAndSmallPatchVertices) {
  qd::approximate::Problem p = with_flaps();
  p.patch.assign(p.patch.size(), 0);
  p.constrained.assign(static_cast<size_t>(p.V.rows()), 1);
  p.constrained[0] = p.constrained[1] = 0;
  const std::string m = message(p);
  EXPECT_TRUE(mentions(m, "2 on non-manifold edges")) << m;
  EXPECT_TRUE(mentions(m, "or repair the mesh")) << m;
}

TEST(Validate, PatchVectorOfWrongSize) {
  qd::approximate::Problem p = two_patches();
  p.patch.pop_back();
  const std::string m = message(p);
  EXPECT_TRUE(mentions(m, "17 patch ids for 18 faces")) << m;
}

TEST(Validate, ConstrainedVectorOfWrongSize) {
  qd::approximate::Problem p = two_patches();
  p.constrained.assign(3, 0);
  const std::string m = message(p);
  EXPECT_TRUE(mentions(m, "3 constrained flags for 16 vertices")) << m;
}

TEST(Validate, TooSmallPatchPassesWithAWarning) {
  qd::approximate::Problem p = two_patches();
  p.patch[17] = 7;
  p.patch[16] = 7;
  p.patch[0] = 3;
  const qd::common::Topology t = qd::approximate::validate(p);
  EXPECT_EQ(t.small_patches, 2);
  EXPECT_TRUE(t.in_small_patch[0] && t.in_small_patch[1] && t.in_small_patch[5]);
  EXPECT_FALSE(t.in_small_patch[6]);
  const std::vector<std::string> w = qd::approximate::warnings(t);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_TRUE(mentions(w[0], "2 patches have fewer than 4 faces (first: patch 3, 1 face)")) << w[0];
  EXPECT_TRUE(mentions(w[0], "left unchanged")) << w[0];
}

TEST(Validate, AllPatchesTooSmall) {
  qd::approximate::Problem p = two_patches();
  for (size_t f = 0; f < p.patch.size(); ++f) p.patch[f] = static_cast<int>(f / 3);
  const std::string m = message(p);
  EXPECT_TRUE(mentions(m, "Patch 0 has only 3 faces (6 patches have fewer than ")) << m;
  EXPECT_TRUE(mentions(m, std::to_string(qd::common::kMinPatchFaces))) << m;
}

TEST(Validate, InconsistentOrientationInPatch) {
  qd::approximate::Problem p = two_patches();
  std::swap(p.F(10, 1), p.F(10, 2));  // face 10 lies in patch 1
  const std::string m = message(p);
  EXPECT_TRUE(mentions(m, "Patch 1")) << m;
  EXPECT_TRUE(mentions(m, "10")) << m;
  EXPECT_TRUE(mentions(m, "Re-Orient all faces coherently")) << m;
}

TEST(Validate, AllVerticesSelected) {
  qd::approximate::Problem p = two_patches();
  p.constrained.assign(16, 1);
  const std::string m = message(p);
  EXPECT_TRUE(mentions(m, "All 16 vertices are constrained")) << m;
}

TEST(Validate, SeamsAndBoundaryLeaveNothingFree) {
  // 3×3 grid split into two columns: the only interior vertex lies on the seam.
  qd::approximate::Problem p = grid(3);
  for (int f = 0; f < p.F.rows(); ++f) p.patch.push_back((f / 2) % 2);
  EXPECT_TRUE(mentions(message(p), "constrained"));
  p.params.seams = qd::approximate::SeamMode::Free;
  EXPECT_EQ(message(p), "");
  p.params.seams = qd::approximate::SeamMode::Fixed;
  p.params.keep_boundary = false;
  EXPECT_EQ(message(p), "");
}

TEST(Validate, BadTolerance) {
  qd::approximate::Problem p = two_patches();
  for (const double tol : {0.0, -1.0, kNaN, kInf}) {
    p.params.tolerance = tol;
    EXPECT_TRUE(mentions(message(p), "tolerance")) << tol;
  }
}

TEST(Validate, BadPatchTolerance) {
  qd::approximate::Problem p = two_patches();
  p.params.patch_tolerance[1] = 0.2;
  EXPECT_EQ(message(p), "");
  p.params.patch_tolerance[0] = -0.5;
  EXPECT_TRUE(mentions(message(p), "patch 0"));
}

TEST(Validate, BadIterationCount) {
  qd::approximate::Problem p = two_patches();
  for (const int n : {0, -3, 10001}) {
    p.params.max_iter = n;
    EXPECT_TRUE(mentions(message(p), "iterations is " + std::to_string(n))) << n;
  }
}

TEST(Validate, BadWeightAndAnchor) {
  qd::approximate::Problem p = two_patches();
  p.params.weight = 0;
  EXPECT_TRUE(mentions(message(p), "weight w"));
  p.params.weight = 30;
  p.params.anchor = -1;
  EXPECT_TRUE(mentions(message(p), "anchor"));
  p.params.anchor = kNaN;
  EXPECT_TRUE(mentions(message(p), "anchor"));
  p.params.anchor = 0;  // no anchor is allowed
  EXPECT_EQ(message(p), "");
}

TEST(Validate, BadStopThresholds) {
  qd::approximate::Problem p = two_patches();
  for (const double x : {-0.1, 100.0, kNaN}) {
    p.params.stop_abd = x;
    EXPECT_TRUE(mentions(message(p), "ABD")) << x;
    p.params.stop_abd = 1;
    p.params.stop_obd = x;
    EXPECT_TRUE(mentions(message(p), "OBD")) << x;
    p.params.stop_obd = 1;
  }
  p.params.stop_abd = 0;
  EXPECT_EQ(message(p), "");
}

TEST(Validate, IsolatedVertexIsFine) {
  qd::approximate::Problem p = two_patches();
  append_vertex(p, 5, 5, 5);
  p.constrained.assign(17, 0);
  const qd::common::Topology t = qd::approximate::validate(p);
  EXPECT_FALSE(t.used[16]);
  EXPECT_TRUE(t.used[15]);
}

TEST(Validate, SinglePatchWithoutIdsIsFine) {
  qd::approximate::Problem p = grid(4);
  EXPECT_EQ(message(p), "");
  // Without ids there are no seams.
  const qd::common::Topology t = qd::approximate::validate(p);
  for (const char s : t.seam) EXPECT_FALSE(s);
}

TEST(Validate, MessagesAreOneLine) {
  qd::approximate::Problem p = two_patches();
  p.F(10, 1) = 40;
  const std::string m = message(p);
  ASSERT_FALSE(m.empty());
  EXPECT_EQ(m.find('\n'), std::string::npos);
}

}  // namespace
