// The --report JSON, read back with nlohmann-json: every figure bit-identical, the keys in the
// order written, NaN as null, and valid UTF-8 whatever bytes the file names and notes hold.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "report_json.h"

namespace {

using Json = nlohmann::ordered_json;

qd::Result sample_result() {
  qd::Result r;
  r.average_edge = 0.1;
  r.abd_reduction = 100.0 / 3.0;
  r.total_before.g_abd = 1e-300;
  r.total_after.max_abs_k = std::numeric_limits<double>::quiet_NaN();
  qd::PatchReport p;
  p.id = 7;
  p.tolerance = 0.3;
  p.developability = "defect";
  qd::IterationReport it;
  it.iteration = 1;
  it.ratio_abd = 2.0 / 3.0;
  it.note = "quote \" backslash \\ newline \n";
  p.history.push_back(it);
  r.patches.push_back(p);
  r.warnings.push_back("1 patch has fewer than 4 faces");
  return r;
}

Json report(const qd::Result& r, const std::vector<std::string>& notes) {
  qd::cli::Options o;
  o.input = "in\xff.ply";  // not UTF-8
  o.output = "out.ply";
  o.patch_tolerance_ae[7] = 3.0;
  qd::Params params = o.params;
  params.patch_tolerance[7] = 0.3;
  const qd::cli::ReportContext context{o, params, 3, 1, true, 0, notes};
  return Json::parse(qd::cli::report_json(r, context));
}

TEST(ReportJson, ReadsBackBitIdentical) {
  const qd::Result r = sample_result();
  const Json j = report(r, {"polygons fan-triangulated"});
  EXPECT_EQ(j["average_edge"].get<double>(), 0.1);
  EXPECT_EQ(j["abd_reduction"].get<double>(), r.abd_reduction);
  EXPECT_EQ(j["total_before"]["g_abd"].get<double>(), 1e-300);
  EXPECT_TRUE(j["total_after"]["max_abs_k"].is_null());
  const Json& patch = j["patches"][0];
  EXPECT_EQ(patch["id"].get<int>(), 7);
  EXPECT_EQ(patch["tolerance_ae"].get<double>(), 0.3 / 0.1);
  EXPECT_EQ(patch["developability"], "defect");
  EXPECT_EQ(patch["history"][0]["ratio_abd"].get<double>(), 2.0 / 3.0);
  EXPECT_EQ(patch["history"][0]["note"], r.patches[0].history[0].note);
  EXPECT_EQ(j["parameters"]["patch_tolerance"][0]["tolerance_ae"].get<double>(), 3.0);
  EXPECT_EQ(j["parameters"]["seams"], "fixed");
  EXPECT_EQ(j["parameters"]["quality"], "curvature");
  EXPECT_EQ(j["warnings"][0], r.warnings[0]);
  EXPECT_EQ(j["notes"][0], "polygons fan-triangulated");
}

TEST(ReportJson, KeepsTheKeyOrderAndWritesValidUtf8) {
  const Json j = report(sample_result(), {"property 'q\xc3' ignored"});
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  const std::vector<std::string> expected = {
      "input", "output", "vertices", "faces", "has_patch_ids", "constrained_vertices",
      "average_edge", "parameters", "total_before", "total_after", "abd_reduction",
      "factorizations", "time_ms", "stage_ms", "patches", "warnings", "notes", "log"};
  EXPECT_EQ(keys, expected);
  EXPECT_EQ(j["input"], "in\xef\xbf\xbd.ply");  // U+FFFD for the stray byte
  EXPECT_EQ(j["notes"][0], "property 'q\xef\xbf\xbd' ignored");
}

}  // namespace
