// PLY reader/writer: round trips in the three formats, pass-through, and mesh extraction.
#include <gtest/gtest.h>

#include "io/ply_mesh.h"
#include "io/ply_reader.h"
#include "io/ply_writer.h"
#include "ply_test_util.h"

using namespace qd::io;
using namespace qd::io::test;

namespace {

void expect_same_tables(const PlyTables& a, const PlyTables& b) {
  EXPECT_EQ(a.comments, b.comments);
  EXPECT_EQ(a.obj_info, b.obj_info);
  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (std::size_t e = 0; e < a.elements.size(); ++e) {
    const PlyElement& x = a.elements[e];
    const PlyElement& y = b.elements[e];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.count, y.count);
    ASSERT_EQ(x.properties.size(), y.properties.size());
    for (std::size_t p = 0; p < x.properties.size(); ++p) {
      EXPECT_EQ(x.properties[p].name, y.properties[p].name);
      EXPECT_EQ(x.properties[p].type(), y.properties[p].type());
      EXPECT_EQ(x.properties[p].is_list, y.properties[p].is_list);
      EXPECT_EQ(x.properties[p].values, y.properties[p].values) << x.properties[p].name;
      EXPECT_EQ(x.properties[p].offsets, y.properties[p].offsets) << x.properties[p].name;
    }
  }
}

PlyTables every_scalar_type() {
  PlyTables ply;
  PlyElement e;
  e.name = "thing";
  e.count = 3;
  e.properties = {scalar_property("a", ScalarType::Int8, {-128, 0, 127}),
                  scalar_property("b", ScalarType::UInt8, {0, 1, 255}),
                  scalar_property("c", ScalarType::Int16, {-32768, 5, 32767}),
                  scalar_property("d", ScalarType::UInt16, {0, 6, 65535}),
                  scalar_property("e", ScalarType::Int32, {-2147483648.0, 7, 2147483647.0}),
                  scalar_property("f", ScalarType::UInt32, {0, 8, 4294967295.0}),
                  scalar_property("g", ScalarType::Float32, {-1.5f, 0.1f, 3.4e38f}),
                  scalar_property("h", ScalarType::Float64, {-1e-300, 0.1, 1.0 / 3.0}),
                  list("l", ScalarType::UInt16, ScalarType::Int16, {{}, {1, -2}, {3, 4, 5, 6}})};
  ply.elements = {e};
  return ply;
}

class RoundTrip : public ::testing::TestWithParam<PlyFormat> {};

TEST_P(RoundTrip, EveryScalarTypeAndListsAreBitIdentical) {
  const PlyTables ply = every_scalar_type();
  const PlyTables back = parse_ply_tables(serialize_ply_tables(ply, GetParam()));
  EXPECT_EQ(back.format, GetParam());
  expect_same_tables(ply, back);
}

TEST_P(RoundTrip, MeshTablesCommentsAndUnknownElementsSurvive) {
  const PlyTables ply = sample_ply();
  expect_same_tables(ply, parse_ply_tables(serialize_ply_tables(ply, GetParam())));
}

INSTANTIATE_TEST_SUITE_P(Formats, RoundTrip,
                         ::testing::Values(PlyFormat::Ascii, PlyFormat::BinaryLittleEndian,
                                           PlyFormat::BinaryBigEndian));

TEST(PlyBigEndian, BytesAreInNetworkOrder) {
  PlyTables ply;
  PlyElement e;
  e.name = "n";
  e.count = 1;
  e.properties = {scalar_property("v", ScalarType::UInt32, {0x01020304})};
  ply.elements = {e};
  const std::string bytes = serialize_ply_tables(ply, PlyFormat::BinaryBigEndian);
  EXPECT_EQ(bytes.substr(bytes.size() - 4), std::string("\x01\x02\x03\x04", 4));
  const std::string little = serialize_ply_tables(ply, PlyFormat::BinaryLittleEndian);
  EXPECT_EQ(little.substr(little.size() - 4), std::string("\x04\x03\x02\x01", 4));
}

TEST(PlyMesh, ExtractsTrianglesPatchesSelectionAndKeepsTheRest) {
  const MeshDocument mesh =
      mesh_of(serialize_ply_tables(sample_ply(), PlyFormat::BinaryLittleEndian));
  ASSERT_EQ(mesh.positions.size(), 5u);
  EXPECT_EQ(mesh.positions[4], (std::array<double, 3>{2, 0.5, 0.25}));
  // The quad (1 4 2 0) becomes (1 4 2) and (1 2 0).
  ASSERT_EQ(mesh.triangles.size(), 4u);
  EXPECT_EQ(mesh.triangles[2], (std::array<int, 3>{1, 4, 2}));
  EXPECT_EQ(mesh.triangles[3], (std::array<int, 3>{1, 2, 0}));
  EXPECT_EQ(mesh.patch, (std::vector<int>{1, 1, 2, 2}));
  EXPECT_EQ(mesh.constrained, (std::vector<char>{0, 0, 0, 0, 1}));
  ASSERT_EQ(mesh.notes.size(), 1u);
  EXPECT_NE(mesh.notes[0].find("fan-triangulated"), std::string::npos);
  // Vertex extras: flags and temperature, without x y z.
  ASSERT_EQ(mesh.vertex_extra.size(), 2u);
  EXPECT_EQ(mesh.vertex_extra[1].name, "temperature");
  EXPECT_EQ(mesh.vertex_extra[1].values.to_doubles(),
            (std::vector<double>{-7, 3, 100, -32768, 32767}));
  // Face extras: texcoord split per corner for the quad, quality repeated.
  ASSERT_EQ(mesh.face_extra.size(), 2u);
  const PlyProperty& uv = mesh.face_extra[0];
  ASSERT_EQ(uv.offsets.size(), 5u);
  const std::vector<double> uv_values = uv.values.to_doubles();
  EXPECT_EQ(std::vector<double>(uv_values.begin() + 12, uv_values.begin() + 18),
            (std::vector<double>{0.5, 0.25, 0.75, 0.125, 1, 0.5}));
  EXPECT_EQ(std::vector<double>(uv_values.begin() + 18, uv_values.end()),
            (std::vector<double>{0.5, 0.25, 1, 0.5, 0, 0}));
  EXPECT_EQ(mesh.face_extra[1].values.to_doubles(), (std::vector<double>{1, 1, 2.2f, 2.2f}));
  ASSERT_EQ(mesh.other_elements.size(), 1u);
  EXPECT_EQ(mesh.other_elements[0].name, "edge");
  EXPECT_EQ(mesh.comments.size(), 2u);
}

TEST(PlyMesh, IntegerPatchPropertyIsUsedWithoutQuality) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_index\nproperty int patch\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 7\n";
  const MeshDocument mesh = mesh_of(text);
  EXPECT_EQ(mesh.patch, (std::vector<int>{7}));
  EXPECT_TRUE(mesh.constrained.empty());
  EXPECT_TRUE(mesh.notes.empty());
}

TEST(PlyMesh, FloatFlagsOfAnyValueReadWithoutOverflow) {
  // 32.5 truncates to the selection bit; 1e300, -1e19 and nan cannot hold it (and would overflow
  // a cast to an integer).
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
      "property float z\nproperty double flags\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n"
      "0 0 0 32.5\n1 0 0 1e300\n0 1 0 -1e19\n1 1 0 nan\n2 2 0 -32\n3 0 1 2\n";
  const MeshDocument mesh = mesh_of(text);
  EXPECT_EQ(mesh.constrained, (std::vector<char>{1, 0, 0, 0, 1}));
}

TEST(PlyReader, AcceptsCrLfHeadersSignsAndSkipsBlankHeaderLines) {
  const std::string text =
      "ply\r\nformat ascii 1.0\r\ncomment  two  spaces\r\n\r\nelement vertex 3\r\nproperty double "
      "x\r\n"
      "property double y\r\nproperty double z\r\nelement face 1\r\n"
      "property list uchar uint vertex_indices\r\nend_header\r\n+1 -2 3e2\r\n0 0 0\r\n1 1 1\r\n3 0 "
      "1 2\r\n";
  const PlyTables ply = parse_ply_tables(text);
  EXPECT_EQ(ply.comments, (std::vector<std::string>{" two  spaces"}));
  EXPECT_EQ(ply.elements[0].properties[2].values[0], 300.0);
  EXPECT_EQ(ply.elements[0].properties[1].values[0], -2.0);
}

}  // namespace
