// What the caller gives beside the mesh: existing patches kept where they fit and split where
// they do not, selection borders kept, components and non-manifold or misoriented parts kept
// apart, and bad input refused with a message saying what to do.
#include <gtest/gtest.h>

#include <functional>

#include "common/error.h"
#include "segment/segment.h"
#include "segment_checks.h"
#include "segment_meshes.h"

namespace qd::test {
namespace {

using namespace qd::common;
using namespace qd::segment;

double centroid_y(const SegmentProblem& p, size_t f) {
  const auto i = static_cast<Eigen::Index>(f);
  return p.V(p.F(i, 0), 1) + p.V(p.F(i, 1), 1) + p.V(p.F(i, 2), 1);
}

bool logged(const SegmentResult& r, const std::string& text) {
  for (const std::string& line : r.warnings)
    if (line.find(text) != std::string::npos) return true;
  return false;
}

TEST(SegmentInput, ExistingPatchesThatFitAreKept) {
  const MeshBuilder b = cone_on_cylinder();
  SegmentProblem p = b.problem();
  for (size_t f = 0; f < b.pieces().size(); ++f)  // cylinder in two halves (ids 4, 5), cone 9
    p.patch.push_back(b.pieces()[f] == 1 ? 9 : centroid_y(p, f) > 0 ? 4 : 5);
  const SegmentResult r = segment::segment(p);
  expect_valid(p, r);
  ASSERT_EQ(r.patches.size(), 3u);
  for (size_t f = 0; f < r.patch.size(); ++f)
    EXPECT_EQ(r.patches[r.patch[f]].source_patch, p.patch[f]);
  for (const SegmentPatch& s : r.patches) EXPECT_TRUE(s.kept);
}

TEST(SegmentInput, OnlyPatchesTooFarFromDevelopableAreSplit) {
  const MeshBuilder b = capped_cylinder();
  SegmentProblem p = b.problem();
  for (const int piece : b.pieces()) p.patch.push_back(piece == 1 ? 5 : 7);  // top; side + bottom
  p.params.crease_deg = 180;  // the fit alone must split patch 7
  const SegmentResult r = segment_into_pieces(b.pieces(), p);
  for (size_t f = 0; f < r.patch.size(); ++f) {
    const SegmentPatch& s = r.patches[r.patch[f]];
    EXPECT_EQ(s.source_patch, p.patch[f]);
    EXPECT_EQ(s.kept, p.patch[f] == 5);
  }
}

TEST(SegmentInput, SelectionBordersAreKept) {
  const MeshBuilder b = cone_on_cylinder();
  SegmentProblem p = b.problem();
  for (size_t f = 0; f < b.pieces().size(); ++f)  // half of the cylinder and of the cone
    p.selected.push_back(centroid_y(p, f) > 0);
  const SegmentResult r = segment::segment(p);
  expect_valid(p, r);
  EXPECT_EQ(r.patches.size(), 4u);
  std::map<int, std::set<char>> states;
  for (size_t f = 0; f < r.patch.size(); ++f) states[r.patch[f]].insert(p.selected[f]);
  for (const auto& [patch, s] : states) EXPECT_EQ(s.size(), 1u) << "patch " << patch;
}

TEST(SegmentInput, ComponentsAreSegmentedApart) {
  MeshBuilder b = capped_cylinder(24, 8, 3);
  b.grid([](double u, double v) { return Vec3(5 + u, v, 0.0); }, 6, 6, 3);  // a square beside it
  segment_into_pieces(b.pieces(), b.problem());
}

TEST(SegmentInput, NonManifoldEdgesAreBordersAndSaidSo) {
  const MeshBuilder b = book();
  const SegmentResult r = segment_into_pieces(b.pieces(), b.problem());
  EXPECT_TRUE(logged(r, "non-manifold"));
}

TEST(SegmentInput, MisorientedFacesAreBordersAndSaidSo) {
  SegmentProblem p = bumped_plane(10, 0.0).problem();
  std::vector<int> block;
  for (int f = 0; f < p.F.rows(); ++f)
    if (p.V(p.F(f, 0), 0) < -0.5 && p.V(p.F(f, 1), 0) < -0.5 && p.V(p.F(f, 2), 0) < -0.5) {
      std::swap(p.F(f, 1), p.F(f, 2));
      block.push_back(f);
    }
  const SegmentResult r = segment::segment(p);
  expect_valid(p, r);
  EXPECT_EQ(r.patches.size(), 2u);
  for (const int f : block) EXPECT_EQ(r.patch[f], r.patch[block.front()]);
  EXPECT_TRUE(logged(r, "orientation"));
}

// The call fails with qd::common::Error whose message holds `hint`.
void expect_refused(const std::function<void(SegmentProblem&)>& spoil, const std::string& hint) {
  SegmentProblem p = cube(3).problem();
  spoil(p);
  try {
    segment::segment(p);
    ADD_FAILURE() << "accepted; expected: " << hint;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(hint), std::string::npos) << e.what();
  }
}

TEST(SegmentInput, BadMeshesAreRefusedWithWhatToDo) {
  expect_refused([](SegmentProblem& p) { p.V.resize(0, 3); }, "no vertices");
  expect_refused([](SegmentProblem& p) { p.F.resize(0, 3); }, "no faces");
  expect_refused([](SegmentProblem& p) { p.V(2, 1) = std::nan(""); }, "NaN");
  expect_refused([](SegmentProblem& p) { p.F(4, 2) = 1000; }, "refers to vertex 1000");
  expect_refused([](SegmentProblem& p) { p.F(4, 2) = p.F(4, 0); }, "twice");
  expect_refused([](SegmentProblem& p) { p.V.row(p.F(0, 2)) = p.V.row(p.F(0, 0)); }, "zero-area");
  expect_refused(
      [](SegmentProblem& p) {
        p.F.conservativeResize(p.F.rows() + 1, 3);
        p.F.row(p.F.rows() - 1) = p.F.row(0);
      },
      "duplicate");
  expect_refused([](SegmentProblem& p) { p.patch = {1, 2}; }, "patch ids");
  expect_refused([](SegmentProblem& p) { p.selected = {1}; }, "selection flags");
}

TEST(SegmentInput, AbsurdParametersAreRefusedWithWhatToDo) {
  expect_refused([](SegmentProblem& p) { p.params.max_error_deg = 0; }, "largest fit error");
  expect_refused([](SegmentProblem& p) { p.params.max_error_deg = 95; }, "e.g. 20");
  expect_refused([](SegmentProblem& p) { p.params.max_error_deg = std::nan(""); }, "in degrees");
  expect_refused([](SegmentProblem& p) { p.params.min_faces = 0; }, "smallest patch size");
  expect_refused([](SegmentProblem& p) { p.params.min_area = 1.5; }, "smallest patch area");
  expect_refused([](SegmentProblem& p) { p.params.target_patches = -1; }, "target patch count");
  expect_refused([](SegmentProblem& p) { p.params.crease_deg = 0; }, "crease angle");
  expect_refused([](SegmentProblem& p) { p.params.weights.boundary = -1; }, "boundary weight");
  expect_refused([](SegmentProblem& p) { p.params.max_rounds = 0; }, "Lloyd rounds");
  expect_refused([](SegmentProblem& p) { p.params.threads = -2; }, "threads");
}

}  // namespace
}  // namespace qd::test
