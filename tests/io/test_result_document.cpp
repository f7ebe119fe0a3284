// Each job's output document (io/result_document.h): the result's columns on a copy of the input
// document, as written to PLY, and a result of the wrong size refused.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "common/error.h"
#include "io/output_mesh.h"
#include "io/ply_reader.h"
#include "io/result_document.h"
#include "segment/patch_color.h"

using namespace qd;
using namespace qd::io;

namespace {

using namespace qd::common;
using namespace qd::segment;

// One triangle with float positions.
MeshDocument triangle() {
  MeshDocument m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.position_types = {ScalarType::Float32, ScalarType::Float32, ScalarType::Float32};
  m.triangles = {{0, 1, 2}};
  return m;
}

// The tables of the document's PLY bytes.
PlyTables tables(const MeshDocument& doc) {
  return parse_ply_tables(serialize_ply(doc, PlyFormat::BinaryLittleEndian));
}

const PlyProperty& column(const PlyTables& ply, const char* element, const char* name) {
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

TEST(ResultDocument, ApproximationWritesPositionsAndTheChosenQuality) {
  approximate::Result r;
  r.V = Positions::Zero(3, 3);
  r.V(2, 1) = 7;
  r.k_after = {-1, 0, 1};
  r.displacement = {0, 0.5, 2};
  params::ApproximateSettings s;
  PlyTables ply = tables(approximated_document(triangle(), r, s));
  EXPECT_EQ(column(ply, "vertex", "y").type(), ScalarType::Float64);
  EXPECT_EQ(column(ply, "vertex", "y").values[2], 7);
  EXPECT_EQ(column(ply, "vertex", "quality").values.to_doubles(), r.k_after);
  EXPECT_EQ(column(ply, "vertex", "red").values[0], 255);   // lowest K: red
  EXPECT_EQ(column(ply, "vertex", "blue").values[2], 255);  // highest K: blue
  s.output_quality = params::QualityKind::Displacement;
  s.colorize = false;
  ply = tables(approximated_document(triangle(), r, s));
  EXPECT_EQ(column(ply, "vertex", "quality").values.to_doubles(), r.displacement);
  EXPECT_LT(ply.find("vertex")->find("red"), 0);
  r.displacement.pop_back();
  EXPECT_NE(error_of([&] { approximated_document(triangle(), r, s); }).find("internal error"),
            std::string::npos);
}

TEST(ResultDocument, SegmentationWritesPatchIdsAndColoursPerFace) {
  SegmentResult r;
  r.patch = {3};
  const PlyTables ply = tables(segmented_document(triangle(), r));
  EXPECT_EQ(column(ply, "vertex", "x").type(), ScalarType::Float32);  // vertices untouched
  EXPECT_EQ(column(ply, "face", "quality").values.to_doubles(), (std::vector<double>{3}));
  EXPECT_EQ(column(ply, "face", "green").values[0], patch_color(3)[1]);
  r.patch = {};
  EXPECT_THROW(segmented_document(triangle(), r), Error);
}

TEST(ResultDocument, FlatteningWritesTexcoordsAndStretchPerFace) {
  flatten::FlattenResult r;
  r.uv = flatten::WedgeUV::Zero(1, 6);
  r.uv(0, 3) = 2.5;
  r.stretch = {0.01};
  const PlyTables ply = tables(flattened_document(triangle(), r));
  EXPECT_EQ(column(ply, "face", "texcoord").values[3], 2.5);
  EXPECT_EQ(column(ply, "face", "quality").values.to_doubles(), r.stretch);
  EXPECT_EQ(column(ply, "face", "alpha").values.to_doubles(), (std::vector<double>{255}));
  r.stretch = {};
  EXPECT_THROW(flattened_document(triangle(), r), Error);
}

}  // namespace
