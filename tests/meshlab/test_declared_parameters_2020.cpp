// The MeshLab side of the declared parameters (params/), compiled against MeshLab 2020.09's
// CMeshO: every .mlx sample lists each of its filters' declared parameters in order (the three
// single-filter samples at the defaults), every declared value MeshLab can hand back reaches the
// job's settings, and a bad value is refused naming the parameter.
#include <gtest/gtest.h>

#include <filesystem>

#include "adapter_test_mesh.h"
#include "approximate_params.h"
#include "declared_parameters.h"
#include "flatten_params.h"
#include "mlx_check.h"
#include "param_samples.h"
#include "segment_params.h"

namespace {

using qd::params::Param;

// The sample as MeshLab hands it back: a Choice as its enum index.
qdml::ParamValue as_meshlab(const qd::params::ParamInfo& p, const qd::params::Value& v) {
  if (p.type != qd::params::Type::Choice) return v;
  return static_cast<double>(qdml::choice_index(p, std::get<std::string>(v)));
}

template <typename S>
void expect_every_value_reaches_the_settings(const std::vector<Param<S>>& declared) {
  for (const Param<S>& p : declared) {
    if (!(p.fronts & qd::params::kFilters)) continue;
    const qd::params::Value want = qd::params::test::sample_value(p);
    const S s = qdml::declared_settings(declared, {{p.name, as_meshlab(p, want)}});
    EXPECT_EQ(p.get(s), want) << p.name;
  }
}

}  // namespace

TEST(DeclaredParameters2020, EveryMlxSampleListsTheDeclaredParameters) {
  CMeshO m;
  qdml::test::make_bumpy_cylinder(m);
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(QD_SAMPLES_DIR)) {
    if (entry.path().extension() != ".mlx") continue;
    const std::string stem = entry.path().stem().string();
    for (const qdml::FilterSpec& f : qdml::filter_table()) {
      if (qdml::test::mlx_params(entry.path().string(), f.name).empty()) continue;
      const bool at_defaults = stem == "default" || stem == "segment" || stem == "flatten";
      qdml::test::expect_mlx_lists(entry.path().string(), f.name, f.parameters(m), at_defaults);
      ++checked;
    }
  }
  EXPECT_GE(checked, 10);
}

TEST(DeclaredParameters2020, EveryValueReachesTheSettings) {
  expect_every_value_reaches_the_settings(qd::params::approximate_params());
  expect_every_value_reaches_the_settings(qd::params::segment_params());
  expect_every_value_reaches_the_settings(qd::params::flatten_params());
}

TEST(DeclaredParameters2020, ABadValueIsRefusedNamingTheParameter) {
  const auto refusal = [](const qdml::ParamValues& values) {
    try {
      qdml::declared_settings(qd::params::approximate_params(), values);
    } catch (const qd::common::Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refusal({{"max_iter", 0.0}}), "Max iterations (max_iter) must be at least 1, got 0");
  EXPECT_EQ(refusal({{"tolerance_ae", -1.0}}),
            "Tolerance (AE) (tolerance_ae) must be greater than 0, got -1");
  EXPECT_EQ(refusal({{"seam_mode", 5.0}}), "Seams (seam_mode) has no value number 5");
  EXPECT_EQ(
      refusal({{"patch_tolerance_ae", std::string("3")}}),
      "Per-patch tolerance (AE) (patch_tolerance_ae) expects ID=X items (e.g. 3=0.05), got '3'");
  EXPECT_EQ(refusal({{"weight", 12.0}}), "");
}

TEST(DeclaredParameters2020, TheToleranceTooltipsGiveTheMeshsAverageEdge) {
  CMeshO m;
  qdml::test::make_bumpy_cylinder(m);
  int with_ae = 0;
  for (const qd::params::ParamInfo& p : qdml::filter_table().front().parameters(m))
    with_ae += p.help.find("This mesh: AE = ") != std::string::npos ? 1 : 0;
  EXPECT_EQ(with_ae, 3);  // tolerance_ae, tolerance_model, patch_tolerance_ae
}
