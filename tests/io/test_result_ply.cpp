// Each job's output document (io/result_ply.h): the result's columns on the input's tables, and
// a result of the wrong size refused.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "common/error.h"
#include "io/result_ply.h"
#include "segment/patch_color.h"

using namespace qd;
using namespace qd::meshio;

namespace {

// One triangle with float positions.
MeshFile triangle() {
  MeshFile m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.position_types = {ScalarType::Float32, ScalarType::Float32, ScalarType::Float32};
  m.triangles = {{0, 1, 2}};
  return m;
}

const PlyProperty& column(const PlyFile& ply, const char* element, const char* name) {
  const PlyElement& e = *ply.find(element);
  const int i = e.find(name);
  if (i < 0) throw Error(std::string("no column ") + name);
  return e.properties[static_cast<std::size_t>(i)];
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ResultPly, ApproximationWritesPositionsAndTheChosenQuality) {
  Result r;
  r.V = Positions::Zero(3, 3);
  r.V(2, 1) = 7;
  r.k_after = {-1, 0, 1};
  r.displacement = {0, 0.5, 2};
  params::ApproximateSettings s;
  PlyFile ply = approximated_ply(triangle(), r, s);
  EXPECT_EQ(column(ply, "vertex", "y").type(), ScalarType::Float64);
  EXPECT_EQ(column(ply, "vertex", "y").values[2], 7);
  EXPECT_EQ(column(ply, "vertex", "quality").values.to_doubles(), r.k_after);
  EXPECT_EQ(column(ply, "vertex", "red").values[0], 255);   // lowest K: red
  EXPECT_EQ(column(ply, "vertex", "blue").values[2], 255);  // highest K: blue
  s.output_quality = params::QualityKind::Displacement;
  s.colorize = false;
  ply = approximated_ply(triangle(), r, s);
  EXPECT_EQ(column(ply, "vertex", "quality").values.to_doubles(), r.displacement);
  EXPECT_LT(ply.find("vertex")->find("red"), 0);
  r.displacement.pop_back();
  EXPECT_NE(error_of([&] { approximated_ply(triangle(), r, s); }).find("internal error"),
            std::string::npos);
}

TEST(ResultPly, SegmentationWritesPatchIdsAndColoursPerFace) {
  SegmentResult r;
  r.patch = {3};
  const PlyFile ply = segmented_ply(triangle(), r);
  EXPECT_EQ(column(ply, "vertex", "x").type(), ScalarType::Float32);  // vertices untouched
  EXPECT_EQ(column(ply, "face", "quality").values.to_doubles(), (std::vector<double>{3}));
  EXPECT_EQ(column(ply, "face", "green").values[0], patch_color(3)[1]);
  r.patch = {};
  EXPECT_THROW(segmented_ply(triangle(), r), Error);
}

TEST(ResultPly, FlatteningWritesTexcoordsAndStretchPerFace) {
  FlattenResult r;
  r.uv = WedgeUV::Zero(1, 6);
  r.uv(0, 3) = 2.5;
  r.stretch = {0.01};
  const PlyFile ply = flattened_ply(triangle(), r);
  EXPECT_EQ(column(ply, "face", "texcoord").values[3], 2.5);
  EXPECT_EQ(column(ply, "face", "quality").values.to_doubles(), r.stretch);
  EXPECT_EQ(column(ply, "face", "alpha").values.to_doubles(), (std::vector<double>{255}));
  r.stretch = {};
  EXPECT_THROW(flattened_ply(triangle(), r), Error);
}

}  // namespace
