// Unit tests of the segmentation's MeshLab adapter (segment_adapter) compiled against MeshLab
// 2020.09's CMeshO: apply_segment() writes only per-face quality and colour on success and
// nothing on failure.
#include <common/ml_mesh_type.h>
#include <gtest/gtest.h>
#include <vcg/complex/allocate.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "segment_adapter.h"

namespace {

// Two flat n x n grids folded at a right angle along their shared edge (x = 1, z = 0): the floor
// z = 0 (faces 0 .. 2n² − 1) and the wall x = 1. Together they fit one cone (apex angle 45°), so
// the segmentation keeps them one patch unless a border separates them. No face quality or face
// colour enabled.
void make_folded_sheet(CMeshO& m, int n = 6) {
  m.Clear();
  const int row = n + 1;
  const auto at = [n](int i) { return static_cast<float>(i) / static_cast<float>(n); };
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, static_cast<size_t>(2 * row * row - row));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i, ++vi) vi->P() = CMeshO::CoordType(at(i), at(j), 0);
  for (int k = 1; k <= n; ++k)
    for (int j = 0; j <= n; ++j, ++vi) vi->P() = CMeshO::CoordType(1, at(j), at(k));
  // floor vertex (i, j) = j * row + i; wall vertex (k, j) = floor (n, j) at k = 0, else after the
  // floor
  const auto floor = [row](int i, int j) { return static_cast<size_t>(j * row + i); };
  const auto wall = [row, n](int k, int j) {
    return k == 0 ? static_cast<size_t>(j * row + n)
                  : static_cast<size_t>(row * row + (k - 1) * row + j);
  };
  const auto quad = [&m](size_t a, size_t b, size_t c, size_t d) {
    vcg::tri::Allocator<CMeshO>::AddFace(m, &m.vert[a], &m.vert[b], &m.vert[c]);
    vcg::tri::Allocator<CMeshO>::AddFace(m, &m.vert[a], &m.vert[c], &m.vert[d]);
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      quad(floor(i, j), floor(i + 1, j), floor(i + 1, j + 1), floor(i, j + 1));
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k)
      quad(wall(k, j), wall(k + 1, j), wall(k + 1, j + 1), wall(k, j + 1));
}

}  // namespace

TEST(SegmentAdapter2020, ApplyKeepsTheSelectionBorderAndWritesOnlyFaceQualityAndColour) {
  CMeshO m;
  make_folded_sheet(m);
  const size_t half = m.face.size() / 2;
  for (size_t f = 0; f < half; ++f) m.face[f].SetS();  // the floor
  std::vector<CMeshO::CoordType> positions;
  for (const auto& v : m.vert) positions.push_back(v.cP());
  const qdml::SegmentOutcome out =
      qdml::apply_segment(m, false, qd::params::SegmentSettings{}, nullptr);
  ASSERT_TRUE(out.ok) << out.error;
  ASSERT_TRUE(m.face.IsQualityEnabled() && m.face.IsColorEnabled());
  ASSERT_EQ(out.result.patches.size(), 2u) << testing::PrintToString(out.log);
  std::set<float> floor_ids, wall_ids;
  for (size_t f = 0; f < m.face.size(); ++f)
    (f < half ? floor_ids : wall_ids).insert(m.face[f].Q());
  EXPECT_EQ(floor_ids, std::set<float>{0.0f});
  EXPECT_EQ(wall_ids, std::set<float>{1.0f});
  EXPECT_NE(m.face[0].C(), m.face[half].C());
  for (size_t i = 0; i < m.vert.size(); ++i) EXPECT_EQ(m.vert[i].cP(), positions[i]);
  for (size_t f = 0; f < m.face.size(); ++f) EXPECT_EQ(m.face[f].IsS(), f < half);
}

TEST(SegmentAdapter2020, WithoutABorderTheFoldIsOneCone) {
  CMeshO m;
  make_folded_sheet(m);
  const qdml::SegmentOutcome out =
      qdml::apply_segment(m, false, qd::params::SegmentSettings{}, nullptr);
  ASSERT_TRUE(out.ok) << out.error;
  ASSERT_EQ(out.result.patches.size(), 1u);
  EXPECT_NEAR(out.result.patches[0].proxy.angle, std::acos(-1.0) / 4, 1e-9);
}

TEST(SegmentAdapter2020, FailureLeavesTheMeshUntouched) {
  CMeshO m;
  make_folded_sheet(m);
  qd::params::SegmentSettings settings;
  settings.engine.max_error_deg = 0.0;  // the engine refuses it (the filter's range check first)
  const qdml::SegmentOutcome out = qdml::apply_segment(m, false, settings, nullptr);
  EXPECT_FALSE(out.ok);
  EXPECT_NE(out.error.find("largest fit error"), std::string::npos) << out.error;
  EXPECT_FALSE(m.face.IsQualityEnabled());
  EXPECT_FALSE(m.face.IsColorEnabled());
}
