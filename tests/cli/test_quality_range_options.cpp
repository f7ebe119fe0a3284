// Robust quality range and colour ramp; command-line options and their defaults.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/quality_range.h"
#include "flatten/stretch_ramp.h"
#include "options.h"

namespace {

TEST(QualityRange, PercentilesIgnoreOutliersAndNonFiniteValues) {
  std::vector<double> q;
  for (int i = 0; i <= 100; ++i) q.push_back(i);
  q.push_back(std::numeric_limits<double>::quiet_NaN());
  q.push_back(std::numeric_limits<double>::infinity());
  const qd::QualityRange r = qd::robust_quality_range(q);
  EXPECT_DOUBLE_EQ(r.lo, 2.0);
  EXPECT_DOUBLE_EQ(r.hi, 98.0);
  q.push_back(1e9);  // one outlier barely shifts the range
  EXPECT_LT(qd::robust_quality_range(q).hi, 100.0);
  const qd::QualityRange full = qd::robust_quality_range({3, 1, 2}, 0, 100);
  EXPECT_EQ(full.lo, 1.0);
  EXPECT_EQ(full.hi, 3.0);
  EXPECT_DOUBLE_EQ(qd::robust_quality_range({0, 10}, 25, 50).lo, 2.5);
  EXPECT_EQ(qd::robust_quality_range({}).hi, 0.0);
}

TEST(QualityRange, RampGoesRedGreenBlueAndClamps) {
  const qd::QualityRange r{-1, 1};
  using C = std::array<unsigned char, 3>;
  EXPECT_EQ(qd::ramp_color(-1, r), (C{255, 0, 0}));
  EXPECT_EQ(qd::ramp_color(-5, r), (C{255, 0, 0}));
  EXPECT_EQ(qd::ramp_color(0, r), (C{0, 255, 0}));
  EXPECT_EQ(qd::ramp_color(1, r), (C{0, 0, 255}));
  EXPECT_EQ(qd::ramp_color(7, r), (C{0, 0, 255}));
  EXPECT_EQ(qd::ramp_color(-0.5, r), (C{255, 255, 0}));
  EXPECT_EQ(qd::ramp_color(0.5, r), (C{0, 255, 255}));
  EXPECT_EQ(qd::ramp_color(3, qd::QualityRange{2, 2}), (C{0, 255, 0}));
  // Monotone: red falls then blue rises along the ramp.
  int previous_red = 256, previous_blue = -1;
  for (int i = 0; i <= 40; ++i) {
    const C c = qd::ramp_color(-1 + i / 20.0, r);
    EXPECT_LE(c[0], previous_red);
    EXPECT_GE(c[2], previous_blue);
    previous_red = c[0];
    previous_blue = c[2];
  }
}

TEST(QualityRange, SymmetricRangeCentresZeroWithAFloor) {
  std::vector<double> q;
  for (int i = 0; i <= 100; ++i) q.push_back(i - 70.0);  // |q| up to 70, 98th percentile 68
  q.push_back(std::numeric_limits<double>::quiet_NaN());
  const qd::QualityRange r = qd::symmetric_quality_range(q, 1.0);
  EXPECT_DOUBLE_EQ(r.hi, 68.0);
  EXPECT_DOUBLE_EQ(r.lo, -68.0);
  EXPECT_EQ(qd::symmetric_quality_range({1e-9, -2e-9}, 0.5).hi, 0.5);
  EXPECT_EQ(qd::symmetric_quality_range({}, 0.5).lo, -0.5);
  // The stretch ramp: exact developments (round-off only) read green; ±0.1 % at its ends.
  const qd::QualityRange stretch = qd::stretch_ramp_range({1e-12, -3e-12, 0});
  EXPECT_EQ(qd::ramp_color(-3e-12, stretch), (std::array<unsigned char, 3>{0, 255, 0}));
  EXPECT_EQ(stretch.hi, qd::kStretchRampFloor);
}

qd::cli::ApproximateOptions parse(std::vector<std::string> args) {
  return qd::cli::parse_command_line(args).approximate;
}

// What the command prints and exits 0 for (--help, --version), "" when it runs a job.
std::string printed(std::vector<std::string> args) { return qd::cli::parse_command_line(args).print; }

std::string usage_error(std::vector<std::string> args) {
  try {
    parse(args);
  } catch (const qd::cli::UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(Options, DefaultsComeFromParams) {
  const qd::cli::ApproximateOptions o = parse({"in.ply", "out.ply"});
  const qd::Params d;
  EXPECT_EQ(o.input, "in.ply");
  EXPECT_EQ(o.output, "out.ply");
  EXPECT_EQ(o.tolerance_ae, qd::cli::kDefaultToleranceAE);
  EXPECT_EQ(o.params.max_iter, d.max_iter);
  EXPECT_EQ(o.params.weight, d.weight);
  EXPECT_EQ(o.params.anchor, d.anchor);
  EXPECT_EQ(o.params.stop_abd, d.stop_abd);
  EXPECT_EQ(o.params.stop_obd, d.stop_obd);
  EXPECT_EQ(o.params.seams, d.seams);
  EXPECT_EQ(o.params.targets, d.targets);
  EXPECT_EQ(o.params.tolerance_mode, d.tolerance_mode);
  EXPECT_EQ(o.params.keep_boundary, d.keep_boundary);
  EXPECT_TRUE(o.color);
  EXPECT_TRUE(o.report.empty());
}

TEST(Options, ParsesEveryOption) {
  const qd::cli::ApproximateOptions o =
      parse({"--tolerance", "0.5", "in.obj", "--tolerance-mode=total", "--max-iter", "3", "--seams",
             "free", "--free-boundary", "--weight", "12", "--anchor", "0", "--targets", "refit",
             "--stop-abd", "0.5", "--stop-obd=2", "--patch-tolerance", "2=0.01", "--patch-tolerance",
             "-1=3", "--constraints", "c.txt", "--quality", "displacement", "--no-color", "--report",
             "r.json", "--quiet", "--progress", "out.ply"});
  EXPECT_EQ(o.input, "in.obj");
  EXPECT_EQ(o.output, "out.ply");
  EXPECT_EQ(o.tolerance_ae, 0.5);
  EXPECT_EQ(o.params.tolerance_mode, qd::ToleranceMode::Total);
  EXPECT_EQ(o.params.max_iter, 3);
  EXPECT_EQ(o.params.seams, qd::SeamMode::Free);
  EXPECT_FALSE(o.params.keep_boundary);
  EXPECT_EQ(o.params.weight, 12);
  EXPECT_EQ(o.params.anchor, 0);
  EXPECT_EQ(o.params.targets, qd::TargetMode::Refit);
  EXPECT_EQ(o.params.stop_abd, 0.5);
  EXPECT_EQ(o.params.stop_obd, 2);
  EXPECT_EQ(o.patch_tolerance_ae, (std::map<int, double>{{-1, 3.0}, {2, 0.01}}));
  EXPECT_EQ(o.constraints, "c.txt");
  EXPECT_EQ(o.quality, qd::cli::QualityKind::Displacement);
  EXPECT_FALSE(o.color);
  EXPECT_EQ(o.report, "r.json");
  EXPECT_TRUE(o.quiet);
  EXPECT_EQ(o.progress, qd::cli::ProgressMode::On);
}

TEST(Options, RejectsBadCommandLines) {
  const std::pair<std::vector<std::string>, const char*> cases[] = {
      {{"in.ply"}, "expected INPUT and OUTPUT, got 1"},
      {{"a", "b", "c"}, "got 3"},
      {{"a", "b", "--frobnicate"}, "unknown option '--frobnicate'"},
      {{"a", "b", "--tolerance", "-1"}, "--tolerance must be greater than 0, got -1"},
      {{"a", "b", "--tolerance", "0"}, "--tolerance must be greater than 0"},
      {{"a", "b", "--tolerance", "nan"}, "--tolerance expects a finite number, got 'nan'"},
      {{"a", "b", "--tolerance"}, "--tolerance needs a value"},
      {{"a", "b", "--max-iter", "0"}, "--max-iter expects a whole number from 1 to 100000, got '0'"},
      {{"a", "b", "--max-iter", "2.5"}, "--max-iter expects a whole number"},
      {{"a", "b", "--weight", "nan"}, "--weight expects a finite number"},
      {{"a", "b", "--anchor", "-2"}, "--anchor must not be negative"},
      {{"a", "b", "--seams", "loose"}, "--seams expects fixed|free, got 'loose'"},
      {{"a", "b", "--targets", "x"}, "--targets expects fixed|reproject|refit"},
      {{"a", "b", "--tolerance-mode", "x"}, "--tolerance-mode expects step|total"},
      {{"a", "b", "--patch-tolerance", "3"}, "--patch-tolerance expects ID=X"},
      {{"a", "b", "--patch-tolerance", "3=-1"}, "--patch-tolerance must be greater than 0"},
      {{"a", "a"}, "OUTPUT is the INPUT file; pass --overwrite-input"},
      {{"a", "b", "--report", "b"}, "the --report file must differ"},
  };
  for (const auto& [args, expected] : cases) {
    const std::string message = usage_error(args);
    EXPECT_NE(message.find(expected), std::string::npos) << "got '" << message << "'";
  }
  EXPECT_TRUE(usage_error({"a", "a", "--overwrite-input"}).empty());
  EXPECT_FALSE(printed({"--help"}).empty());
  EXPECT_EQ(printed({"--version"}), std::string("quasidev ") + QD_VERSION + "\n");
  EXPECT_EQ(parse({"--", "-in.ply", "out.ply"}).input, "-in.ply");
}

TEST(Options, SubcommandTakesTheSameOptionsAndMessages) {
  EXPECT_EQ(parse({"approximate", "in.ply", "out.ply", "--seams", "free"}).params.seams,
            qd::SeamMode::Free);
  EXPECT_EQ(parse({"approximate", "in.ply", "out.ply"}).input, "in.ply");
  const std::string message = usage_error({"approximate", "a", "b", "--weight", "-3"});
  EXPECT_NE(message.find("--weight must be greater than 0, got -3"), std::string::npos) << message;
  EXPECT_EQ(printed({"approximate", "--version"}), printed({"--version"}));
  // The last of repeated or contradicting options wins, as on every command line.
  const qd::cli::ApproximateOptions o =
      parse({"a", "b", "--free-boundary", "--keep-boundary", "--max-iter", "3", "--max-iter=4"});
  EXPECT_TRUE(o.params.keep_boundary);
  EXPECT_EQ(o.params.max_iter, 4);
}

TEST(Options, FlattenHasItsOwnOptionsAndDefaults) {
  const qd::cli::CommandLine plain = qd::cli::parse_command_line({"flatten", "in.ply", "out.ply"});
  EXPECT_EQ(plain.job, qd::cli::Job::Flatten);
  const qd::FlattenParams d;
  EXPECT_EQ(plain.flatten.params.max_iterations, d.max_iterations);
  EXPECT_EQ(plain.flatten.params.tolerance, d.tolerance);
  EXPECT_EQ(plain.flatten.params.gap, d.gap);
  EXPECT_EQ(plain.flatten.unit, qd::cli::PatternUnit::Model);
  EXPECT_TRUE(plain.flatten.svg.empty() && plain.flatten.dxf.empty());
  const qd::cli::FlattenOptions o =
      qd::cli::parse_command_line({"flatten", "in.obj", "out.ply", "--svg", "p.svg", "--dxf=p.dxf",
                                   "--unit", "in", "--max-iter", "0", "--tolerance", "0",
                                   "--gap", "2", "--notch-spacing", "3.5", "--threads", "1",
                                   "--solver", "eigen-llt", "--report", "r.json", "--quiet"})
          .flatten;
  EXPECT_EQ(o.input, "in.obj");
  EXPECT_EQ(o.svg, "p.svg");
  EXPECT_EQ(o.dxf, "p.dxf");
  EXPECT_EQ(o.unit, qd::cli::PatternUnit::Inch);
  EXPECT_EQ(o.params.max_iterations, 0);
  EXPECT_EQ(o.params.tolerance, 0);
  EXPECT_EQ(o.params.gap, 2);
  EXPECT_EQ(o.params.notch_spacing, 3.5);
  EXPECT_EQ(o.params.threads, 1);
  EXPECT_EQ(o.params.solver, qd::SolverKind::EigenLLT);
  EXPECT_EQ(o.report, "r.json");
  EXPECT_TRUE(o.quiet);
  // The approximation's options are not the flattening's, and the other way round.
  const auto rejected = [](std::vector<std::string> args) {
    try {
      qd::cli::parse_command_line(std::move(args));
    } catch (const qd::cli::UsageError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(rejected({"flatten", "a", "b", "--seams", "free"}).find("unknown option '--seams'"),
            std::string::npos);
  EXPECT_NE(rejected({"a", "b", "--svg", "p.svg"}).find("unknown option '--svg'"), std::string::npos);
  EXPECT_NE(rejected({"flatten", "a", "b", "--svg", "b"}).find("the --svg file must differ"),
            std::string::npos);
  EXPECT_NE(rejected({"flatten", "a", "b", "--svg", "x", "--dxf", "x"}).find("--svg and --dxf files must differ"),
            std::string::npos);
  EXPECT_NE(rejected({"flatten", "a"}).find("expected INPUT and OUTPUT, got 1"), std::string::npos);
}

TEST(Options, HelpNamesEveryOptionAndTheDefaults) {
  const std::string help = printed({"approximate", "--help"});
  for (const char* option :
       {"--report", "--tolerance ", "--tolerance-mode", "--max-iter", "--seams", "--keep-boundary",
        "--free-boundary", "--weight", "--anchor", "--targets", "--stop-abd", "--stop-obd",
        "--patch-tolerance", "--constraints", "--quality", "--no-color", "--progress", "--quiet",
        "--version", "--help", "--overwrite-input"})
    EXPECT_NE(help.find(option), std::string::npos) << option;
  const qd::Params d;
  EXPECT_NE(help.find("(default " + std::to_string(d.max_iter) + ")"), std::string::npos);
  EXPECT_NE(help.find("reproject)"), std::string::npos);
  const std::string top = printed({"--help"});
  EXPECT_NE(top.find("Subcommands:"), std::string::npos) << top;
  EXPECT_NE(top.find("approximate"), std::string::npos) << top;
  EXPECT_NE(top.find("--max-iter"), std::string::npos) << top;
}

}  // namespace
