// Unit tests of the segmentation's MeshLab adapter (segment_adapter) compiled against MeshLab
// 2020.09's CMeshO: sample_meshes/segment.mlx and segment_then_approximate.mlx list every
// parameter of their filters (meshlabserver 2020.09 aborts otherwise) at the defaults, and
// apply_segment() writes only per-face quality and colour on success and nothing on failure.
#include <gtest/gtest.h>

#include <QDomDocument>
#include <QFile>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <common/ml_mesh_type.h>
#include <vcg/complex/allocate.h>

#include "quasidev_adapter.h"
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
  // floor vertex (i, j) = j * row + i; wall vertex (k, j) = floor (n, j) at k = 0, else after the floor
  const auto floor = [row](int i, int j) { return static_cast<size_t>(j * row + i); };
  const auto wall = [row, n](int k, int j) {
    return k == 0 ? static_cast<size_t>(j * row + n) : static_cast<size_t>(row * row + (k - 1) * row + j);
  };
  const auto quad = [&m](size_t a, size_t b, size_t c, size_t d) {
    vcg::tri::Allocator<CMeshO>::AddFace(m, &m.vert[a], &m.vert[b], &m.vert[c]);
    vcg::tri::Allocator<CMeshO>::AddFace(m, &m.vert[a], &m.vert[c], &m.vert[d]);
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) quad(floor(i, j), floor(i + 1, j), floor(i + 1, j + 1), floor(i, j + 1));
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) quad(wall(k, j), wall(k + 1, j), wall(k + 1, j + 1), wall(k, j + 1));
}

// The <Param> elements of the index-th <filter> of an .mlx file.
QDomNodeList mlx_params(const char* path, int index) {
  QFile file(path);
  EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path;
  QDomDocument doc;
  EXPECT_TRUE(doc.setContent(&file)) << path;
  return doc.elementsByTagName("filter").at(index).toElement().elementsByTagName("Param");
}

std::vector<std::string> names(const QDomNodeList& params) {
  std::vector<std::string> out;
  for (int i = 0; i < params.size(); ++i) out.push_back(params.at(i).toElement().attribute("name").toStdString());
  return out;
}

std::vector<std::string> names(const std::vector<qdml::ParamSpec>& specs) {
  std::vector<std::string> out;
  for (const qdml::ParamSpec& s : specs) out.push_back(s.name);
  return out;
}

qdml::ParamValues defaults() {
  qdml::ParamValues values;
  for (const qdml::ParamSpec& spec : qdml::segment_parameter_specs()) values[spec.name] = spec.value;
  return values;
}

}  // namespace

TEST(SegmentAdapter2020, SegmentMlxListsEveryParameterAtItsDefault) {
  const QDomNodeList params = mlx_params(QD_SEGMENT_MLX, 0);
  const std::vector<qdml::ParamSpec> specs = qdml::segment_parameter_specs();
  ASSERT_EQ(names(params), names(specs));
  for (int i = 0; i < params.size(); ++i) {
    const QDomElement p = params.at(i).toElement();
    const qdml::ParamSpec& spec = specs[static_cast<size_t>(i)];
    const char* type = spec.kind == qdml::ParamKind::Float  ? "RichFloat"
                       : spec.kind == qdml::ParamKind::Int  ? "RichInt"
                       : spec.kind == qdml::ParamKind::Bool ? "RichBool"
                                                            : "RichEnum";
    EXPECT_EQ(p.attribute("type").toStdString(), type) << spec.name;
    if (spec.kind == qdml::ParamKind::Bool)
      EXPECT_EQ(p.attribute("value") == "true", spec.value != 0) << spec.name;
    else
      EXPECT_EQ(p.attribute("value").toDouble(), spec.value) << spec.name;
  }
}

TEST(SegmentAdapter2020, PipelineMlxListsEveryParameterOfBothFilters) {
  CMeshO m;
  make_folded_sheet(m);
  EXPECT_EQ(names(mlx_params(QD_PIPELINE_MLX, 0)), names(qdml::segment_parameter_specs()));
  EXPECT_EQ(names(mlx_params(QD_PIPELINE_MLX, 1)), names(qdml::parameter_specs(m)));
}

TEST(SegmentAdapter2020, SettingsFollowTheValues) {
  qdml::ParamValues values = defaults();
  const qdml::SegmentSettings d = qdml::segment_settings_from_values(values);
  const qd::SegmentParams engine;
  EXPECT_EQ(d.params.max_error_deg, engine.max_error_deg);
  EXPECT_EQ(d.params.min_faces, engine.min_faces);
  EXPECT_FALSE(d.keep_patches);
  EXPECT_TRUE(d.selection_border);
  values["max_error_deg"] = 30.0;
  values["target_patches"] = 4.0;
  values["keep_patches"] = 1.0;
  values["crease_deg"] = 180.0;
  const qdml::SegmentSettings s = qdml::segment_settings_from_values(values);
  EXPECT_EQ(s.params.max_error_deg, 30);
  EXPECT_EQ(s.params.target_patches, 4);
  EXPECT_TRUE(s.keep_patches);
  EXPECT_EQ(s.params.crease_deg, 180);
}

TEST(SegmentAdapter2020, ApplyKeepsTheSelectionBorderAndWritesOnlyFaceQualityAndColour) {
  CMeshO m;
  make_folded_sheet(m);
  const size_t half = m.face.size() / 2;
  for (size_t f = 0; f < half; ++f) m.face[f].SetS();  // the floor
  std::vector<CMeshO::CoordType> positions;
  for (const auto& v : m.vert) positions.push_back(v.cP());
  const qdml::SegmentOutcome out = qdml::apply_segment(m, false, qdml::segment_settings_from_values(defaults()), nullptr);
  ASSERT_TRUE(out.ok) << out.error;
  ASSERT_TRUE(m.face.IsQualityEnabled() && m.face.IsColorEnabled());
  ASSERT_EQ(out.result.patches.size(), 2u) << testing::PrintToString(out.log);
  std::set<float> floor_ids, wall_ids;
  for (size_t f = 0; f < m.face.size(); ++f) (f < half ? floor_ids : wall_ids).insert(m.face[f].Q());
  EXPECT_EQ(floor_ids, std::set<float>{0.0f});
  EXPECT_EQ(wall_ids, std::set<float>{1.0f});
  EXPECT_NE(m.face[0].C(), m.face[half].C());
  for (size_t i = 0; i < m.vert.size(); ++i) EXPECT_EQ(m.vert[i].cP(), positions[i]);
  for (size_t f = 0; f < m.face.size(); ++f) EXPECT_EQ(m.face[f].IsS(), f < half);
}

TEST(SegmentAdapter2020, WithoutABorderTheFoldIsOneCone) {
  CMeshO m;
  make_folded_sheet(m);
  const qdml::SegmentOutcome out = qdml::apply_segment(m, false, qdml::segment_settings_from_values(defaults()), nullptr);
  ASSERT_TRUE(out.ok) << out.error;
  ASSERT_EQ(out.result.patches.size(), 1u);
  EXPECT_NEAR(out.result.patches[0].proxy.angle, std::acos(-1.0) / 4, 1e-9);
}

TEST(SegmentAdapter2020, FailureLeavesTheMeshUntouched) {
  CMeshO m;
  make_folded_sheet(m);
  qdml::ParamValues values = defaults();
  values["max_error_deg"] = 0.0;
  const qdml::SegmentOutcome out = qdml::apply_segment(m, false, qdml::segment_settings_from_values(values), nullptr);
  EXPECT_FALSE(out.ok);
  EXPECT_NE(out.error.find("largest fit error"), std::string::npos) << out.error;
  EXPECT_FALSE(m.face.IsQualityEnabled());
  EXPECT_FALSE(m.face.IsColorEnabled());
}
