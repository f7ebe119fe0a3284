// Output PLY: new positions as double, quality and colours added or replaced, every other
// property passed through unchanged, normals recomputed; atomic file replacement; constraints.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "common/error.h"
#include "io/atomic_file.h"
#include "io/constraint_file.h"
#include "io/mesh_reader.h"
#include "io/output_mesh.h"
#include "io/ply_reader.h"
#include "io/ply_writer.h"
#include "ply_test_util.h"

using namespace qd::io;
using namespace qd::io::test;

namespace {

using namespace qd::common;

// The output of `m` moved up by 0.1, with vertex quality 0.5 i and, if asked, colours.
MeshDocument shifted(const MeshDocument& m, bool colors) {
  MeshDocument out = m;
  qd::common::Positions V(static_cast<Eigen::Index>(m.positions.size()), 3);
  std::vector<double> quality;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const auto& p = m.positions[i];
    V.row(static_cast<Eigen::Index>(i)) << p[0], p[1], p[2] + 0.1;
    quality.push_back(0.5 * static_cast<double>(i));
  }
  set_positions(out, V);
  set_quality(out, Element::Vertex, quality);
  if (colors)
    set_colors(out, Element::Vertex,
               std::vector<std::array<unsigned char, 3>>(V.rows(), {10, 20, 30}));
  return out;
}

TEST(OutputMesh, PassesThroughEverythingItDoesNotOwn) {
  PlyTables in = sample_ply();
  in.elements[0].properties.push_back(
      scalar_property("quality", ScalarType::Float32, {9, 9, 9, 9, 9}));
  in.elements[0].properties.push_back(scalar_property("red", ScalarType::UInt8, {1, 2, 3, 4, 5}));
  const MeshDocument mesh = mesh_of(serialize_ply_tables(in, PlyFormat::BinaryBigEndian));
  const PlyTables out =
      parse_ply_tables(serialize_ply(shifted(mesh, true), PlyFormat::BinaryLittleEndian));
  const PlyElement& v = out.elements[0];
  ASSERT_EQ(v.name, "vertex");
  EXPECT_EQ(v.properties[0].type(), ScalarType::Float64);
  EXPECT_EQ(v.properties[2].values[4], 0.25 + 0.1);
  EXPECT_EQ(v.properties[v.find("temperature")].values.to_doubles(),
            (std::vector<double>{-7, 3, 100, -32768, 32767}));
  EXPECT_EQ(v.properties[v.find("flags")].values[4], 0x20);
  EXPECT_EQ(v.properties[v.find("quality")].values.to_doubles(),
            (std::vector<double>{0, 0.5, 1, 1.5, 2}));
  EXPECT_EQ(v.properties[v.find("red")].values.to_doubles(), std::vector<double>(5, 10));
  EXPECT_EQ(v.properties[v.find("alpha")].values.to_doubles(), std::vector<double>(5, 255));
  int quality_columns = 0;
  for (const PlyProperty& p : v.properties) quality_columns += p.name == "quality";
  EXPECT_EQ(quality_columns, 1);
  const PlyElement& f = out.elements[1];
  EXPECT_EQ(f.count, 4u);
  EXPECT_EQ(f.properties[f.find("texcoord")].values, mesh.face_extra[0].values);
  EXPECT_EQ(f.properties[f.find("quality")].values, mesh.face_extra[1].values);
  EXPECT_EQ(out.elements[2].name, "edge");
  EXPECT_EQ(out.elements[2].properties[1].values.to_doubles(), (std::vector<double>{0.1, 1e-300}));
  EXPECT_EQ(out.comments, in.comments);
}

TEST(OutputMesh, WithoutColoursTheInputColoursStay) {
  PlyTables in = sample_ply();
  in.elements[0].properties.push_back(scalar_property("red", ScalarType::UInt8, {1, 2, 3, 4, 5}));
  const MeshDocument mesh = mesh_of(serialize_ply_tables(in, PlyFormat::Ascii));
  const PlyTables out = parse_ply_tables(serialize_ply(shifted(mesh, false), PlyFormat::Ascii));
  const PlyElement& v = out.elements[0];
  EXPECT_EQ(v.properties[v.find("red")].values.to_doubles(), (std::vector<double>{1, 2, 3, 4, 5}));
  EXPECT_LT(v.find("alpha"), 0);
}

TEST(OutputMesh, PerFaceFieldsReplaceTheirOwnAndKeepTheVertices) {
  const PlyTables in = sample_ply();  // x is float: it stays so when the vertices do not move
  const MeshDocument mesh = mesh_of(serialize_ply_tables(in, PlyFormat::BinaryLittleEndian));
  const std::size_t nf = mesh.triangles.size();
  MeshDocument written = mesh;
  qd::flatten::WedgeUV uv(static_cast<Eigen::Index>(nf), 6);
  uv.rowwise() = Eigen::Matrix<double, 1, 6>(0.5, 1, 1.5, 2, 2.5, 3);
  set_texcoords(written, uv);
  set_quality(written, Element::Face, std::vector<double>(nf, -0.25));
  set_colors(written, Element::Face, std::vector<std::array<unsigned char, 3>>(nf, {1, 2, 3}));
  const PlyTables out = parse_ply_tables(serialize_ply(written, PlyFormat::BinaryLittleEndian));
  const PlyElement& v = out.elements[0];
  EXPECT_EQ(v.properties[0].type(), ScalarType::Float32);
  EXPECT_EQ(v.properties[1].type(), in.elements[0].properties[1].type());
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_EQ(v.properties[k].values, in.elements[0].properties[k].values);
  EXPECT_EQ(v.properties.size(), in.elements[0].properties.size());  // nothing added per vertex
  const PlyElement& face = out.elements[1];
  int texcoords = 0, qualities = 0;
  for (const PlyProperty& p : face.properties) {
    texcoords += p.name == "texcoord";
    qualities += p.name == "quality";
  }
  EXPECT_EQ(texcoords, 1);
  EXPECT_EQ(qualities, 1);
  const PlyProperty& texcoord = face.properties[face.find("texcoord")];
  EXPECT_EQ(texcoord.type(), ScalarType::Float32);
  EXPECT_EQ(texcoord.count_type, ScalarType::UInt8);
  const std::vector<double> uv_values = texcoord.values.to_doubles();
  EXPECT_EQ(std::vector<double>(uv_values.begin(), uv_values.begin() + 6),
            (std::vector<double>{0.5, 1, 1.5, 2, 2.5, 3}));
  EXPECT_EQ(face.properties[face.find("quality")].type(), ScalarType::Float64);
  EXPECT_EQ(face.properties[face.find("quality")].values.to_doubles(),
            std::vector<double>(4, -0.25));
  EXPECT_EQ(face.properties[face.find("green")].values.to_doubles(), std::vector<double>(4, 2));
  EXPECT_EQ(face.properties[face.find("alpha")].values.to_doubles(), std::vector<double>(4, 255));
  EXPECT_THROW(set_quality(written, Element::Face, {1.0}), qd::common::Error);
}

TEST(OutputMesh, VertexNormalsAreRecomputed) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
      "z\n"
      "property float nx\nproperty float ny\nproperty float nz\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n0 0 0 1 0 0\n1 0 0 1 0 0\n0 1 0 1 0 "
      "0\n3 0 1 2\n";
  const MeshDocument mesh = mesh_of(text);
  ASSERT_EQ(mesh.vertex_extra.size(), 3u);  // nx ny nz
  MeshDocument out = mesh;
  qd::common::Positions V(3, 3);
  V << 0, 0, 0, 0, 1, 0, 0, 0, 1;  // now in the x = 0 plane, normal +x
  set_positions(out, V);
  EXPECT_EQ(out.position_types[0], ScalarType::Float64);
  EXPECT_DOUBLE_EQ(out.vertex_extra[0].values[0], 1.0);
  EXPECT_DOUBLE_EQ(out.vertex_extra[2].values[2], 0.0);
  EXPECT_EQ(out.vertex_extra[0].type(), ScalarType::Float32);  // the normals keep their type
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0;                              // back in z = 0: normal +z
  MeshDocument again = mesh;
  set_positions(again, V);
  EXPECT_DOUBLE_EQ(again.vertex_extra[2].values[1], 1.0);
}

class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("qd_cli_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const char* name) const { return (dir_ / name).string(); }
  static void write(const std::string& p, const std::string& content) {
    std::ofstream(p) << content;
  }
  std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir_), {}));
  }
  std::filesystem::path dir_;
};

TEST_F(TempDir, PendingFileReplacesOnlyOnCommit) {
  const std::string target = path("out.ply");
  write(target, "old");
  {
    PendingFile pending(target, "new");
    EXPECT_EQ(read_file_bytes(target), "old");
    EXPECT_EQ(entries(), 2u);
  }
  EXPECT_EQ(read_file_bytes(target), "old");
  EXPECT_EQ(entries(), 1u);  // the temporary file is gone
  PendingFile pending(target, "new");
  pending.commit();
  EXPECT_EQ(read_file_bytes(target), "new");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(TempDir, PendingFileInMissingDirectoryFails) {
  EXPECT_NE(
      error_of([&] { PendingFile p(path("no/such/dir/out.ply"), "x"); }).find("cannot create"),
      std::string::npos);
}

TEST_F(TempDir, ReadMeshDispatchesAndNamesTheFile) {
  write(path("m.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write(path("m.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  write(path("empty.ply"), "");
  write(path("nofaces.obj"), "v 0 0 0\n");
  write(path("m.stl"), "solid x\n");
  EXPECT_EQ(read_mesh(path("m.obj")).triangles.size(), 1u);
  EXPECT_EQ(read_mesh(path("m.off")).triangles.size(), 1u);
  EXPECT_NE(error_of([&] { read_mesh(path("empty.ply")); }).find("is empty"), std::string::npos);
  EXPECT_NE(error_of([&] { read_mesh(path("nofaces.obj")); }).find("has no faces"),
            std::string::npos);
  EXPECT_NE(error_of([&] { read_mesh(path("m.stl")); }).find("unknown mesh format"),
            std::string::npos);
  EXPECT_NE(error_of([&] { read_mesh(path("missing.ply")); }).find("cannot open"),
            std::string::npos);
  EXPECT_NE(error_of([&] { read_mesh(dir_.string()); }).find("not a regular file"),
            std::string::npos);
}

TEST_F(TempDir, ConstraintFile) {
  write(path("c.txt"), "# selected\n3\n\n 0  # first\n3\n");
  EXPECT_EQ(read_constraint_file(path("c.txt"), 4), (std::vector<std::size_t>{3, 0, 3}));
  write(path("bad.txt"), "1\n4\n");
  EXPECT_NE(error_of([&] {
              read_constraint_file(path("bad.txt"), 4);
            }).find("line 2: vertex index 4 is out of range (the mesh has 4 vertices"),
            std::string::npos);
  write(path("word.txt"), "1 2\n");
  EXPECT_NE(error_of([&] {
              read_constraint_file(path("word.txt"), 4);
            }).find("one vertex index per line"),
            std::string::npos);
}

}  // namespace

namespace {

// The fuzzer's seeds must be valid files, so that mutations start from deep inside the parsers.
TEST(FuzzSeeds, EverySeedIsAValidMesh) {
  int seeds = 0;
  for (const auto& entry : std::filesystem::directory_iterator(QD_FUZZ_SEEDS)) {
    const MeshDocument m = read_mesh(entry.path().string());
    EXPECT_GE(m.triangles.size(), 2u) << entry.path();
    ++seeds;
  }
  EXPECT_GE(seeds, 5);
}

}  // namespace
