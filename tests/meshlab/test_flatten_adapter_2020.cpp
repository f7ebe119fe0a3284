// Unit tests of the shared MeshLab adapter of the flattening (flatten_adapter) compiled against
// MeshLab 2020.09's CMeshO: apply_flatten() writes only wedge texture coordinates (in model
// units), face quality and face colour on success, the pattern files asked for, and nothing on
// failure.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <string>

#include "adapter_test_mesh.h"
#include "flatten_adapter.h"

namespace {

using qdml::test::make_bumpy_cylinder;
using qdml::test::Snapshot;
using qdml::test::snapshot;

// One directory per test: ctest runs the tests in processes of their own, two of which may start
// in the same millisecond and so share gtest's time-based random seed.
std::filesystem::path temp_dir() {
  const auto dir =
      std::filesystem::temp_directory_path() /
      ("qd_flatten_adapter_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
       "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST(FlattenAdapter2020, WritesTexcoordsInModelUnitsStretchAndColourOnly) {
  CMeshO m;
  make_bumpy_cylinder(m, 24, 12, 0.0);  // exactly developable
  for (size_t f = 0; f < m.face.size(); ++f) m.face[f].Q() = f < m.face.size() / 2 ? 0.f : 1.f;
  auto extra = vcg::tri::Allocator<CMeshO>::AddVertices(m, 1);  // deleted: skipped, kept
  extra->P() = CMeshO::CoordType(5, 5, 5);
  vcg::tri::Allocator<CMeshO>::DeleteVertex(m, m.vert.back());
  m.vert[3].SetS();
  const Snapshot before = snapshot(m);
  const std::filesystem::path dir = temp_dir();
  qd::params::FlattenSettings settings;
  settings.svg_file = (dir / "p.svg").string();
  settings.dxf_file = (dir / "p.dxf").string();
  const qdml::FlattenOutcome out = qdml::apply_flatten(m, true, settings, nullptr);
  ASSERT_TRUE(out.ok) << out.error;
  const Snapshot after = snapshot(m);
  EXPECT_EQ(after.positions, before.positions);
  EXPECT_EQ(after.quality, before.quality);
  EXPECT_EQ(after.colours, before.colours);
  EXPECT_EQ(after.vertex_flags, before.vertex_flags);
  EXPECT_EQ(after.face_flags, before.face_flags);
  ASSERT_EQ(out.result.pieces.size(), 2u);
  EXPECT_EQ(out.result.pieces[1].patch, 1);
  // Every edge as long on the pattern as on the mesh, and quality = the engine's stretch.
  double worst = 0;
  for (size_t f = 0; f < m.face.size(); ++f) {
    const CFaceO& face = m.face[f];
    for (int k = 0; k < 3; ++k) {
      const double l3 = static_cast<double>(vcg::Distance(face.cP(k), face.cP((k + 1) % 3)));
      const double l2 =
          static_cast<double>(vcg::Distance(face.cWT(k).P(), face.cWT((k + 1) % 3).P()));
      worst = std::max(worst, std::abs(l2 / l3 - 1));
    }
    EXPECT_FLOAT_EQ(face.cQ(), static_cast<float>(out.result.stretch[f]));
    EXPECT_EQ(face.cC(), vcg::Color4b(0, 255, 0, 255)) << "no stretch reads green";
  }
  EXPECT_LT(worst, 1e-3);
  EXPECT_TRUE(std::filesystem::file_size(dir / "p.svg") > 0);
  EXPECT_TRUE(std::filesystem::file_size(dir / "p.dxf") > 0);
  EXPECT_EQ(out.log.front(), "patches from per-face quality: 2 patch(es)");
  EXPECT_EQ(out.log.back(), "pattern written as DXF to " + settings.dxf_file);
  std::filesystem::remove_all(dir);
}

TEST(FlattenAdapter2020, FailureLeavesTheMeshAndTheFilesUntouched) {
  CMeshO m;
  make_bumpy_cylinder(m);
  m.vert[40].P()[1] = std::numeric_limits<float>::quiet_NaN();
  m.face.DisableWedgeTexCoord();
  m.face.DisableColor();
  const std::filesystem::path dir = temp_dir();
  std::ofstream(dir / "p.svg") << "previous";
  qd::params::FlattenSettings settings;
  settings.svg_file = (dir / "p.svg").string();
  const std::vector<float> quality_before = snapshot(m).face_quality;
  const qdml::FlattenOutcome out = qdml::apply_flatten(m, true, settings, nullptr);
  EXPECT_FALSE(out.ok);
  EXPECT_NE(out.error.find("NaN"), std::string::npos) << out.error;
  EXPECT_FALSE(m.face.IsWedgeTexCoordEnabled());
  EXPECT_FALSE(m.face.IsColorEnabled());
  std::vector<float> quality_after;
  for (const auto& f : m.face) quality_after.push_back(f.cQ());
  EXPECT_EQ(quality_after, quality_before);
  std::ifstream svg(dir / "p.svg");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(svg), {}), "previous");
  std::filesystem::remove_all(dir);
}

TEST(FlattenAdapter2020, AnUnwritablePatternFailsBeforeTheMeshIsWritten) {
  CMeshO m;
  make_bumpy_cylinder(m);
  const Snapshot before = snapshot(m);
  qd::params::FlattenSettings settings;
  settings.dxf_file = "/nonexistent-folder/p.dxf";
  const qdml::FlattenOutcome out = qdml::apply_flatten(m, false, settings, nullptr);
  EXPECT_FALSE(out.ok);
  EXPECT_NE(out.error.find("/nonexistent-folder/p.dxf"), std::string::npos) << out.error;
  const Snapshot after = snapshot(m);
  EXPECT_EQ(after.texcoords, before.texcoords);
  EXPECT_EQ(after.face_quality, before.face_quality);
  EXPECT_EQ(after.face_colours, before.face_colours);
}
