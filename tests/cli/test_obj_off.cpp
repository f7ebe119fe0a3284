// OBJ and OFF readers: corner forms, relative indices, groups as patches, texcoords, polygons,
// and their error messages.
#include <gtest/gtest.h>

#include "io/obj_reader.h"
#include "io/off_reader.h"
#include "io/output_mesh.h"
#include "io/ply_reader.h"
#include "ply_test_util.h"

using namespace qd::io;
using qd::io::test::error_of;

namespace {

const char* kObj =
    "# a comment\n"
    "mtllib x.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0 0.5 0.5 0.5\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "vn 0 0 1\n"
    "g left\n"
    "f 1/1 2/2 3/3\n"
    "o right side\n"
    "f 1/1/1 3/3/1 4/4/1\n"
    "g left\n"
    "f -4/-4 -3/-3 -1/-1   # relative\n"
    "l 1 2\n";

TEST(ObjReader, CornersGroupsAndTexcoords) {
  const MeshDocument m = parse_obj(kObj);
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.positions[2], (std::array<double, 3>{1, 1, 0}));
  ASSERT_EQ(m.triangles.size(), 3u);
  EXPECT_EQ(m.triangles[1], (std::array<int, 3>{0, 2, 3}));
  EXPECT_EQ(m.triangles[2], (std::array<int, 3>{0, 1, 3}));
  EXPECT_EQ(m.patch, (std::vector<int>{0, 1, 0}));
  ASSERT_EQ(m.face_extra.size(), 1u);  // group ids as a column; texcoords are corner_uv
  EXPECT_EQ(m.face_extra[0].name, "patch");
  EXPECT_EQ(m.face_extra[0].type(), ScalarType::Int32);
  EXPECT_EQ(m.face_extra[0].values.to_doubles(), (std::vector<double>{0, 1, 0}));
  ASSERT_EQ(m.corner_uv.size(), 3u);
  EXPECT_EQ(m.corner_uv[2], (std::array<double, 6>{0, 0, 1, 0, 0, 1}));
  ASSERT_EQ(m.notes.size(), 1u);  // the ignored line statement
}

TEST(ObjReader, NoGroupsNoPatchesMixedUvDroppedPolygonSplit) {
  const MeshDocument m =
      parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nf 1 2 3 4\nf 1//1 3//1 4//1\n");
  EXPECT_TRUE(m.patch.empty());
  EXPECT_TRUE(m.face_extra.empty());
  EXPECT_EQ(m.triangles.size(), 3u);
  EXPECT_EQ(m.triangles[1], (std::array<int, 3>{0, 2, 3}));
}

TEST(ObjReader, FacesBeforeTheFirstGroupFormTheirOwnPatch) {
  const MeshDocument m =
      parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\ng a\nf 1 2 3\ng b\nf 3 2 1\n");
  EXPECT_EQ(m.patch, (std::vector<int>{0, 1, 2}));
}

TEST(ObjReader, Errors) {
  const std::pair<const char*, const char*> cases[] = {
      {"v 0 0\n", "OBJ line 1: a vertex needs 3 coordinates"},
      {"v 0 0 x\n", "OBJ line 1: vertex coordinate 'x' is not a finite number"},
      {"v 0 0 nan\n", "is not a finite number"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n",
       "OBJ line 4: vertex index 4 is out of range (3 defined so far)"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "'0' is not a valid vertex index"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n", "vertex index -4 is out of range"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2 2/1 3/1\n", "texture index 2 is out of range"},
      {"v 0 0 0\nv 1 0 0\nf 1 2\n", "OBJ line 3: a face needs at least 3 corners"},
  };
  for (const auto& c : cases) {  // no structured binding: clang 14 cannot capture one
    const std::string message = error_of([&] { parse_obj(c.first); });
    EXPECT_NE(message.find(c.second), std::string::npos) << "got '" << message << "'";
  }
}

TEST(OffReader, ReadsCountsOnTheirOwnLineAndPolygons) {
  const MeshDocument m =
      parse_off("OFF\n# comment\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 255 0 0\n");
  EXPECT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.triangles.size(), 2u);
  EXPECT_TRUE(m.patch.empty());
  const MeshDocument c =
      parse_off("COFF 3 1 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n3 0 1 2\n");
  EXPECT_EQ(c.triangles.size(), 1u);
}

TEST(OffReader, Errors) {
  const std::pair<const char*, const char*> cases[] = {
      {"", "OFF: the file is empty"},
      {"PLY\n", "not an OFF file"},
      {"OFF\n", "the counts line is missing"},
      {"OFF\n1000000000 1 0\n0 0 0\n",
       "declares 1000000000 vertices and 1 faces, but only 1 data lines"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n", "face 0 uses vertex index 5, out of range"},
      // An index of 2^63 or more is read as a double no long long holds (found by the fuzzer).
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9223372036854775807\n",
       "face 0 uses vertex index 9223372036854775808, out of range"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n",
       "OFF line 6: the face lists 3 indices but says it has 4"},
      {"OFF\n3 1 0\n0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n", "OFF line 4: vertex coordinate 'inf'"},
      {"OFF\n-3 1 0\n", "vertex count '-3' is not a non-negative integer"},
  };
  for (const auto& c : cases) {  // no structured binding: clang 14 cannot capture one
    const std::string message = error_of([&] { parse_off(c.first); });
    EXPECT_NE(message.find(c.second), std::string::npos) << "got '" << message << "'";
  }
}

TEST(ObjReader, CornerTexcoordsAreWrittenFirstAmongTheFaceProperties) {
  const PlyTables out =
      parse_ply_tables(serialize_ply(parse_obj(kObj), PlyFormat::BinaryLittleEndian));
  const PlyElement& face = out.elements[1];
  ASSERT_EQ(face.properties.size(), 3u);
  EXPECT_EQ(face.properties[0].name, "vertex_indices");
  EXPECT_EQ(face.properties[1].name, "texcoord");
  EXPECT_EQ(face.properties[2].name, "patch");
  const PlyProperty& uv = face.properties[1];
  EXPECT_EQ(uv.type(), ScalarType::Float32);
  EXPECT_EQ(uv.list_size(2), 6u);
  EXPECT_EQ(uv.values[uv.offsets[2] + 2], 1);  // triangle 2, corner 1: u of vt 2
}

}  // namespace
