// Unit tests of the shared MeshLab adapter (quasidev_adapter) compiled against MeshLab 2020.09's
// CMeshO: apply() writes only positions, quality, colour and normals on success and nothing on
// failure (deleted elements, selection, face quality, face colours and texture coordinates
// untouched).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "adapter_test_mesh.h"
#include "quasidev_adapter.h"

namespace {

using qdml::test::make_bumpy_cylinder;
using qdml::test::Snapshot;
using qdml::test::snapshot;

}  // namespace

TEST(Adapter2020, ApplyWritesOnlyPositionsQualityAndColour) {
  CMeshO m;
  make_bumpy_cylinder(m);
  // A deleted vertex and a deleted face must be skipped and left as they are.
  auto extra = vcg::tri::Allocator<CMeshO>::AddVertices(m, 1);
  extra->P() = CMeshO::CoordType(5, 5, 5);
  vcg::tri::Allocator<CMeshO>::AddFace(m, &m.vert[0], &m.vert[1], &*extra);
  vcg::tri::Allocator<CMeshO>::DeleteFace(m, m.face.back());
  vcg::tri::Allocator<CMeshO>::DeleteVertex(m, m.vert.back());
  const size_t selected = 24 * 6 + 3;  // a vertex near the bump, selected = must not move
  m.vert[selected].SetS();
  const Snapshot before = snapshot(m);

  const qdml::Outcome out = qdml::apply(m, true, qd::params::ApproximateSettings{}, nullptr);
  ASSERT_TRUE(out.ok) << out.error;
  const Snapshot after = snapshot(m);

  EXPECT_EQ(after.vertex_flags, before.vertex_flags);
  EXPECT_EQ(after.face_quality, before.face_quality);
  EXPECT_EQ(after.face_colours, before.face_colours);
  EXPECT_EQ(after.texcoords, before.texcoords);
  EXPECT_EQ(after.face_flags, before.face_flags);
  EXPECT_EQ(after.positions[selected], before.positions[selected]);
  EXPECT_EQ(after.positions.back(), before.positions.back());  // the deleted vertex
  EXPECT_EQ(after.colours.back(), before.colours.back());
  size_t moved = 0;
  for (size_t i = 0; i + 1 < m.vert.size(); ++i) {
    moved += after.positions[i] != before.positions[i] ? 1 : 0;
    EXPECT_FLOAT_EQ(after.quality[i], static_cast<float>(out.result.k_after[i])) << i;
  }
  EXPECT_GT(moved, 0u) << testing::PrintToString(out.log);
  EXPECT_NE(after.colours, before.colours);
  EXPECT_FALSE(out.log.empty());
}

TEST(Adapter2020, FailureLeavesTheMeshUntouched) {
  CMeshO m;
  make_bumpy_cylinder(m);
  m.vert[40].P()[1] = std::numeric_limits<float>::quiet_NaN();
  const Snapshot before = snapshot(m);
  const qdml::Outcome out = qdml::apply(m, true, qd::params::ApproximateSettings{}, nullptr);
  EXPECT_FALSE(out.ok);
  EXPECT_NE(out.error.find("NaN"), std::string::npos) << out.error;
  const Snapshot after = snapshot(m);
  for (size_t i = 0; i < m.vert.size(); ++i) {
    if (i == 40) continue;  // the NaN vertex (NaN != NaN)
    EXPECT_EQ(after.positions[i], before.positions[i]);
  }
  EXPECT_EQ(after.quality, before.quality);
  EXPECT_EQ(after.colours, before.colours);
  EXPECT_EQ(after.vertex_flags, before.vertex_flags);
}

TEST(Adapter2020, TooSmallPatchIsSolvedWithItsNeighbourAndSaysSo) {
  CMeshO m;
  make_bumpy_cylinder(m);
  m.face[10].Q() = 7.2f;  // rounds to patch 7, which has a single face
  const qdml::Outcome out = qdml::apply(m, true, qd::params::ApproximateSettings{}, nullptr);
  ASSERT_TRUE(out.ok) << out.error;
  EXPECT_TRUE(out.result.warnings.empty());
  EXPECT_EQ(std::count_if(out.log.begin(), out.log.end(),
                          [](const std::string& line) {
                            return line.rfind(
                                       "note: patch 7 (1 face) has most of its vertices on seams",
                                       0) == 0;
                          }),
            1);
}
