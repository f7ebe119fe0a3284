// The --report JSON, read back with nlohmann-json: every figure bit-identical, the keys in the
// order written, NaN as null, and valid UTF-8 whatever bytes the file names and notes hold.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "approximate_params.h"
#include "approximate_report_json.h"
#include "marker_report_json.h"
#include "options.h"

namespace {

using Json = nlohmann::ordered_json;

qd::approximate::Result sample_result() {
  qd::approximate::Result r;
  r.average_edge = 0.1;
  r.abd_reduction = 100.0 / 3.0;
  r.total_before.g_abd = 1e-300;
  r.total_after.max_abs_k = std::numeric_limits<double>::quiet_NaN();
  qd::approximate::PatchReport p;
  p.id = 7;
  p.tolerance = 0.3;
  p.developability = qd::approximate::Term::Defect;
  qd::approximate::IterationReport it;
  it.iteration = 1;
  it.ratio_abd = 2.0 / 3.0;
  it.note = "quote \" backslash \\ newline \n";
  p.history.push_back(it);
  r.patches.push_back(p);
  r.warnings.push_back("1 patch has fewer than 4 faces");
  return r;
}

Json report(const qd::approximate::Result& r, const std::vector<std::string>& notes) {
  qd::cli::ApproximateOptions o;
  o.input = "in\xff.ply";  // not UTF-8
  o.output = "out.ply";
  o.settings.patch_tolerance_ae[7] = 3.0;
  const qd::frontend::ReportContext context{o.input, o.output, o.settings, 3, 1, true, 0, notes};
  return Json::parse(qd::frontend::report_json(r, context));
}

TEST(ReportJson, ReadsBackBitIdentical) {
  const qd::approximate::Result r = sample_result();
  const Json j = report(r, {"polygons fan-triangulated"});
  EXPECT_EQ(j["average_edge"].get<double>(), 0.1);
  EXPECT_EQ(j["abd_reduction"].get<double>(), r.abd_reduction);
  EXPECT_EQ(j["total_before"]["g_abd"].get<double>(), 1e-300);
  EXPECT_TRUE(j["total_after"]["max_abs_k"].is_null());
  const Json& patch = j["patches"][0];
  EXPECT_EQ(patch["id"].get<int>(), 7);
  EXPECT_EQ(patch["tolerance_model"].get<double>(), 0.3);
  EXPECT_EQ(patch["tolerance_ae"].get<double>(), 0.3 / 0.1);
  EXPECT_EQ(patch["developability"], "defect");
  EXPECT_EQ(patch["history"][0]["ratio_abd"].get<double>(), 2.0 / 3.0);
  EXPECT_EQ(patch["history"][0]["note"], r.patches[0].history[0].note);
  EXPECT_EQ(j["parameters"]["patch_tolerance_ae"], "7=3");
  EXPECT_EQ(j["parameters"]["seam_mode"], "fixed");
  EXPECT_EQ(j["parameters"]["output_quality"], "curvature");
  EXPECT_EQ(j["parameters"]["max_iter"], qd::approximate::Params().max_iter);  // a whole number
  EXPECT_EQ(j["parameters"]["keep_boundary"], true);
  std::vector<std::string> names;  // every declared parameter, in order
  for (const auto& item : j["parameters"].items()) names.push_back(item.key());
  std::vector<std::string> declared;
  for (const auto& p : qd::params::approximate_params()) declared.push_back(p.name);
  EXPECT_EQ(names, declared);
  EXPECT_EQ(j["warnings"][0], r.warnings[0]);
  EXPECT_EQ(j["notes"][0], "polygons fan-triangulated");
}

TEST(ReportJson, KeepsTheKeyOrderAndWritesValidUtf8) {
  const Json j = report(sample_result(), {"property 'q\xc3' ignored"});
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  const std::vector<std::string> expected = {"input",
                                             "output",
                                             "vertices",
                                             "faces",
                                             "has_patch_ids",
                                             "segmented_first",
                                             "constrained_vertices",
                                             "average_edge",
                                             "parameters",
                                             "total_before",
                                             "total_after",
                                             "abd_reduction",
                                             "factorizations",
                                             "time_ms",
                                             "stage_ms",
                                             "blas_kernels",
                                             "patches",
                                             "joins",
                                             "join_trial",
                                             "warnings",
                                             "notes",
                                             "log"};
  EXPECT_EQ(keys, expected);
  EXPECT_EQ(j["input"], "in\xef\xbf\xbd.ply");  // U+FFFD for the stray byte
  EXPECT_EQ(j["notes"][0], "property 'q\xef\xbf\xbd' ignored");
}

TEST(FlattenReportJson, ReadsBackEveryPieceFigure) {
  qd::flatten::FlattenResult r;
  qd::flatten::PieceReport p;
  p.patch = 3;
  p.component = 1;
  p.label = "3.1";
  p.cut = "cut to a disk along a slit (the patch is closed)";
  p.max_distortion = 1.0 / 3.0;
  p.flattenable = false;
  p.overlapping = 2;
  p.box = Eigen::AlignedBox2d(Eigen::Vector2d(0, 1), Eigen::Vector2d(2, 3));
  r.pieces.push_back(p);
  r.max_distortion = p.max_distortion;
  r.pattern.bounds = p.box;
  qd::flatten::PatternPiece square;  // a 2×2 square sewn, cut with an allowance of 0.5
  square.label = "3.1";
  square.quantity = 2;
  square.mirrored = 1;
  square.outlines = {{{0, 1}, {2, 1}, {2, 3}, {0, 3}}};
  square.cut_outlines = {{{-0.5, 0.5}, {2.5, 0.5}, {2.5, 3.5}, {-0.5, 3.5}}};
  r.pattern.pieces.push_back(square);
  r.groups = {{{0}, {0}, 0.25}};
  r.log = {"patch 3.1: ...", "flattened 1 pieces"};
  qd::cli::FlattenOptions o;
  o.input = "in.ply";
  o.settings.svg_file = "p.svg";
  o.settings.unit = qd::params::PatternUnit::Centimetre;
  o.settings.engine.gap = 0.5;
  const std::vector<std::string> notes = {"polygons fan-triangulated"};
  qd::marker::MarkerChoice marker;
  marker.rows.width = 150;
  marker.rows.length = 80;
  marker.rows.efficiency = 0.75;
  marker.rows.unplaced = {"2"};
  marker.nested.length = 90;
  marker.nested_kept = false;
  const Json j = Json::parse(qd::cli::flatten_report_json(
      r, {o.input, o.output, o.settings, 10, 4, true, notes, r.log}, &marker));
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"input", "output", "vertices", "faces", "has_patch_ids",
                                            "parameters", "pieces", "pattern", "max_distortion",
                                            "flattenable_pieces", "sheet", "time_ms", "notes",
                                            "log", "marker"}));
  const Json& piece = j["pieces"][0];
  EXPECT_EQ(piece["label"], "3.1");
  EXPECT_EQ(piece["component"].get<int>(), 1);
  EXPECT_EQ(piece["cut"], p.cut);
  EXPECT_EQ(piece["max_distortion"].get<double>(), 1.0 / 3.0);
  EXPECT_FALSE(piece["flattenable"].get<bool>());
  EXPECT_EQ(piece["overlapping"].get<int>(), 2);
  EXPECT_EQ(piece["box"]["max"][1].get<double>(), 3.0);
  const Json& cut = j["pattern"][0];
  EXPECT_EQ(cut["label"], "3.1");
  EXPECT_EQ(cut["name"], "");
  EXPECT_EQ(cut["quantity"].get<int>(), 2);
  EXPECT_EQ(cut["mirrored"].get<int>(), 1);
  EXPECT_NEAR(cut["sew_area"].get<double>(), 4, 1e-12);
  EXPECT_NEAR(cut["sew_perimeter"].get<double>(), 8, 1e-12);
  EXPECT_NEAR(cut["cut_area"].get<double>(), 9, 1e-12);
  EXPECT_NEAR(cut["cut_perimeter"].get<double>(), 12, 1e-12);
  EXPECT_EQ(cut["grain"], Json::array({0.0, 1.0}));
  EXPECT_EQ(cut["pieces"][0]["label"], "3.1");
  EXPECT_EQ(cut["difference"].get<double>(), 0.25);
  EXPECT_EQ(j["marker"]["length"].get<double>(), 80.0);
  EXPECT_EQ(j["marker"]["method"], "rows");
  EXPECT_EQ(j["marker"]["nested"]["length"].get<double>(), 90.0);
  EXPECT_EQ(j["marker"]["unplaced"], Json::array({"2"}));
  EXPECT_EQ(j["parameters"]["unit"], "cm");
  EXPECT_EQ(j["parameters"]["gap"].get<double>(), 0.5);
  EXPECT_EQ(j["sheet"]["min"][1].get<double>(), 1.0);
  EXPECT_EQ(j["parameters"]["svg_file"], "p.svg");
  EXPECT_EQ(j["parameters"]["arap_max_iter"], qd::flatten::FlattenParams().max_iterations);
  EXPECT_EQ(j["log"][1], "flattened 1 pieces");
  EXPECT_EQ(j["notes"][0], notes[0]);
}

}  // namespace
