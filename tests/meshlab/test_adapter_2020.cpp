// Unit tests of the shared MeshLab adapter (quasidev_adapter) compiled against MeshLab 2020.09's
// CMeshO: the parameter table against sample_meshes/default.mlx, the settings mapping, and that
// apply() writes only positions, quality, colour and normals on success and nothing on failure
// (deleted elements, selection, face quality, face colours and texture coordinates untouched).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "adapter_test_mesh.h"
#include "mlx_check.h"
#include "quasidev_adapter.h"

namespace {

using qdml::test::make_bumpy_cylinder;
using qdml::test::Snapshot;
using qdml::test::snapshot;

qdml::ParamValues default_values(const CMeshO& m) {
  qdml::ParamValues values;
  for (const qdml::ParamSpec& spec : qdml::parameter_specs(m)) values[spec.name] = spec.value;
  return values;
}

}  // namespace

TEST(Adapter2020, DefaultMlxListsEveryParameterAtItsDefault) {
  CMeshO m;
  make_bumpy_cylinder(m);
  qdml::test::expect_mlx_lists(QD_DEFAULT_MLX, qdml::parameter_specs(m), [](const qdml::ParamSpec& spec, double value) {
    if (spec.name == "tolerance")
      EXPECT_EQ(value, 0.0) << "default.mlx must say 0 (= 1 AE of any mesh)";
    else
      qdml::test::expect_float_default(spec, value);
  });
}

TEST(Adapter2020, ToleranceDefaultIsTheAverageEdgeLength) {
  CMeshO m;
  make_bumpy_cylinder(m);
  const std::vector<qdml::ParamSpec> specs = qdml::parameter_specs(m);
  ASSERT_EQ(specs.front().name, "tolerance");
  // Edges of the grid: around-edges 2 sin(pi/24) ~ 0.261, along-edges 1/6, diagonals ~ 0.31.
  EXPECT_GT(specs.front().value, 1.0 / 6);
  EXPECT_LT(specs.front().value, 0.32);
  EXPECT_NE(specs.front().tooltip.find("AE = "), std::string::npos);
}

TEST(Adapter2020, SettingsFollowTheValues) {
  CMeshO m;
  make_bumpy_cylinder(m);
  qdml::ParamValues values = default_values(m);
  const qdml::Settings defaults = qdml::settings_from_values(values);
  const qd::Params engine_defaults;
  EXPECT_EQ(defaults.params.max_iter, engine_defaults.max_iter);
  EXPECT_EQ(defaults.params.seams, engine_defaults.seams);
  EXPECT_EQ(defaults.params.targets, engine_defaults.targets);
  EXPECT_EQ(defaults.params.weight, engine_defaults.weight);
  values["seam_mode"] = 1.0;
  values["target_mode"] = 2.0;
  values["tolerance_mode"] = 1.0;
  values["keep_boundary"] = 0.0;
  values["output_quality"] = 1.0;
  values["colorize"] = 0.0;
  values["use_patches"] = 0.0;
  values["max_iter"] = 3.0;
  const qdml::Settings s = qdml::settings_from_values(values);
  EXPECT_EQ(s.params.seams, qd::SeamMode::Free);
  EXPECT_EQ(s.params.targets, qd::TargetMode::Refit);
  EXPECT_EQ(s.params.tolerance_mode, qd::ToleranceMode::Total);
  EXPECT_FALSE(s.params.keep_boundary);
  EXPECT_TRUE(s.displacement_quality);
  EXPECT_FALSE(s.colorize);
  EXPECT_FALSE(s.use_patches);
  EXPECT_EQ(s.params.max_iter, 3);
}

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

  const qdml::Outcome out = qdml::apply(m, true, qdml::settings_from_values(default_values(m)), nullptr);
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
  const qdml::Outcome out = qdml::apply(m, true, qdml::settings_from_values(default_values(m)), nullptr);
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
  const qdml::Outcome out = qdml::apply(m, true, qdml::settings_from_values(default_values(m)), nullptr);
  ASSERT_TRUE(out.ok) << out.error;
  EXPECT_TRUE(out.result.warnings.empty());
  EXPECT_EQ(std::count_if(out.log.begin(), out.log.end(),
                          [](const std::string& line) {
                            return line.rfind("note: patch 7 (1 face) has most of its vertices on seams", 0) == 0;
                          }),
            1);
}
