// The command line: every declared parameter of every job is an option that reaches the job's
// settings, under its name and under each older spelling; the defaults are the declaration's;
// bad values are refused naming the option; --help lists every option with its default.
#include <gtest/gtest.h>

#include <regex>

#include "approximate_params.h"
#include "flatten_params.h"
#include "options.h"
#include "param_samples.h"
#include "params_json.h"
#include "segment_params.h"

namespace {

using qd::cli::CommandLine;
using qd::params::Param;

CommandLine parse(std::vector<std::string> args) {
  return qd::cli::parse_command_line(std::move(args));
}

std::string usage_error(std::vector<std::string> args) {
  try {
    parse(std::move(args));
  } catch (const qd::cli::UsageError& e) {
    return e.what();
  }
  return "";
}

// What a parameter needs beside it to be accepted: marker files a fabric width, a PDF a unit.
std::vector<std::string> needed_beside(const std::string& name) {
  if (name == "marker_svg_file" || name == "marker_dxf_file") return {"--marker-width", "150"};
  if (name == "pdf_file") return {"--unit", "cm"};
  return {};
}

// For each parameter of a job that the command has: the value set by `spelling value` (a
// Boolean: by the flag alone) is what get() reads back; checked under the name and every alias.
template <typename S, typename Settings>
void expect_every_option_reaches_the_settings(const std::string& job,
                                              const std::vector<Param<S>>& declared,
                                              Settings settings_of) {
  for (const Param<S>& p : declared) {
    if (!(p.fronts & qd::params::kCommand)) continue;
    const qd::params::Value want = qd::params::test::sample_value(p);
    const std::string option = qd::params::option_name(p.name);
    std::vector<std::vector<std::string>> spellings;
    if (p.type == qd::params::Type::Boolean) {
      const bool on = std::get<double>(want) != 0;
      const auto& aliases = on ? p.aliases : p.off_aliases;
      spellings.push_back({on ? option : "--no-" + option.substr(2)});
      for (const std::string& a : aliases) spellings.push_back({a});
    } else {
      spellings.push_back({option, qd::params::test::sample_text(p)});
      for (const std::string& a : p.aliases)
        spellings.push_back({a, qd::params::test::sample_text(p)});
    }
    for (const std::vector<std::string>& words : spellings) {
      std::vector<std::string> args = {job, "in.ply", "out.ply"};
      args.insert(args.end(), words.begin(), words.end());
      const std::vector<std::string> beside = needed_beside(p.name);
      args.insert(args.end(), beside.begin(), beside.end());
      EXPECT_EQ(p.get(settings_of(parse(args))), want) << job << " " << words.front();
    }
  }
}

TEST(Options, EveryDeclaredParameterIsAnOptionUnderEverySpelling) {
  expect_every_option_reaches_the_settings(
      "approximate", qd::params::approximate_params(),
      [](const CommandLine& l) { return l.approximate.settings; });
  expect_every_option_reaches_the_settings("segment", qd::params::segment_params(),
                                           [](const CommandLine& l) { return l.segment.settings; });
  expect_every_option_reaches_the_settings("flatten", qd::params::flatten_params(),
                                           [](const CommandLine& l) { return l.flatten.settings; });
}

TEST(Options, DefaultsAreTheDeclarations) {
  using qd::params::values_json;
  const CommandLine a = parse({"in.ply", "out.ply"});
  EXPECT_EQ(a.job, qd::cli::Job::Approximate);
  EXPECT_EQ(a.approximate.input, "in.ply");
  EXPECT_EQ(values_json(qd::params::approximate_params(), a.approximate.settings),
            values_json(qd::params::approximate_params(), qd::params::ApproximateSettings{}));
  EXPECT_EQ(
      values_json(qd::params::segment_params(), parse({"segment", "a", "b"}).segment.settings),
      values_json(qd::params::segment_params(), qd::params::SegmentSettings{}));
  EXPECT_EQ(
      values_json(qd::params::flatten_params(), parse({"flatten", "a", "b"}).flatten.settings),
      values_json(qd::params::flatten_params(), qd::params::FlattenSettings{}));
  EXPECT_TRUE(a.approximate.report.empty());
}

// The spellings before the parameters were declared once keep working (issue 24).
TEST(Options, OlderSpellingsKeepWorking) {
  const qd::params::ApproximateSettings a =
      parse({"a", "b", "--tolerance", "0.5", "--patch-tolerance", "2=0.01", "--patch-tolerance",
             "-1=3", "--targets", "refit", "--seams", "free", "--free-boundary", "--quality",
             "displacement", "--no-color", "--constraints", "c.txt"})
          .approximate.settings;
  EXPECT_EQ(a.tolerance_ae, 0.5);
  EXPECT_EQ(a.patch_tolerance_ae, (std::map<int, double>{{-1, 3.0}, {2, 0.01}}));
  EXPECT_EQ(a.engine.targets, qd::approximate::TargetMode::Refit);
  EXPECT_EQ(a.engine.seams, qd::approximate::SeamMode::Free);
  EXPECT_FALSE(a.engine.keep_boundary);
  EXPECT_EQ(a.output_quality, qd::params::QualityKind::Displacement);
  EXPECT_FALSE(a.colorize);
  EXPECT_EQ(a.constraints_file, "c.txt");
  const qd::params::SegmentSettings s =
      parse({"segment", "a", "b", "--max-error", "30", "--target", "3", "--crease", "40"})
          .segment.settings;
  EXPECT_EQ(s.engine.max_error_deg, 30);
  EXPECT_EQ(s.engine.target_patches, 3);
  EXPECT_EQ(s.engine.crease_deg, 40);
  const qd::params::FlattenSettings f =
      parse({"flatten", "a", "b", "--max-iter", "5", "--tolerance", "0.01", "--svg", "p.svg",
             "--dxf", "p.dxf"})
          .flatten.settings;
  EXPECT_EQ(f.engine.max_iterations, 5);
  EXPECT_EQ(f.engine.tolerance, 0.01);
  EXPECT_EQ(f.svg_file, "p.svg");
  EXPECT_EQ(f.dxf_file, "p.dxf");
}

TEST(Options, RejectsBadCommandLines) {
  const std::pair<std::vector<std::string>, const char*> cases[] = {
      {{"in.ply"}, "expected INPUT and OUTPUT, got 1"},
      {{"a", "b", "c"}, "got 3"},
      {{"a", "b", "--frobnicate"}, "unknown option '--frobnicate'"},
      {{"a", "b", "--tolerance-ae", "-1"}, "--tolerance-ae must be greater than 0, got -1"},
      {{"a", "b", "--tolerance", "0"}, "--tolerance-ae must be greater than 0"},
      {{"a", "b", "--tolerance-ae", "nan"}, "--tolerance-ae expects a finite number, got 'nan'"},
      {{"a", "b", "--tolerance-ae"}, "--tolerance-ae needs a value"},
      {{"a", "b", "--tolerance-model", "-1"}, "--tolerance-model must not be negative, got -1"},
      {{"a", "b", "--max-iter", "0"}, "--max-iter expects a whole number from 1 to 10000, got '0'"},
      {{"a", "b", "--max-iter", "2.5"}, "--max-iter expects a whole number"},
      {{"a", "b", "--weight", "nan"}, "--weight expects a finite number"},
      {{"a", "b", "--anchor", "-2"}, "--anchor must not be negative"},
      {{"a", "b", "--seam-mode", "loose"}, "--seam-mode expects fixed|free, got 'loose'"},
      {{"a", "b", "--targets", "x"}, "--target-mode expects fixed|reproject|refit"},
      {{"a", "b", "--tolerance-mode", "x"}, "--tolerance-mode expects step|total"},
      {{"a", "b", "--patch-tolerance-ae", "3"}, "--patch-tolerance-ae expects ID=X items"},
      {{"a", "b", "--patch-tolerance", "3=-1"},
       "--patch-tolerance-ae for patch 3 must be greater than 0"},
      {{"segment", "a", "b", "--max-error-deg", "91"}, "--max-error-deg must be at most 90"},
      {{"flatten", "a", "b", "--arap-tolerance", "1"}, "--arap-tolerance must be below 1"},
      {{"a", "a"}, "OUTPUT is the INPUT file; pass --overwrite-input"},
      {{"a", "b", "--report", "b"}, "the --report file must differ"},
      {{"flatten", "a", "b", "--seam-mode", "free"}, "unknown option '--seam-mode'"},
      {{"a", "b", "--svg-file", "p.svg"}, "unknown option '--svg-file'"},
      {{"flatten", "a", "b", "--svg", "b"}, "the --svg-file file must differ"},
      {{"flatten", "a", "b", "--svg-file", "x", "--dxf-file", "x"},
       "--svg-file and --dxf-file files must differ"},
  };
  for (const auto& [args, expected] : cases) {
    const std::string message = usage_error(args);
    EXPECT_NE(message.find(expected), std::string::npos) << "got '" << message << "'";
  }
  EXPECT_TRUE(usage_error({"a", "a", "--overwrite-input"}).empty());
  EXPECT_FALSE(parse({"--help"}).print.empty());
  EXPECT_EQ(parse({"--version"}).print, std::string("quasidev ") + QD_VERSION + "\n");
  EXPECT_EQ(parse({"approximate", "--version"}).print, parse({"--version"}).print);
  EXPECT_EQ(parse({"--", "-in.ply", "out.ply"}).approximate.input, "-in.ply");
}

// The last of repeated or contradicting options wins, as on every command line.
TEST(Options, TheLastOccurrenceWins) {
  const qd::params::ApproximateSettings s =
      parse({"a", "b", "--free-boundary", "--keep-boundary", "--max-iter", "3", "--max-iter=4"})
          .approximate.settings;
  EXPECT_TRUE(s.engine.keep_boundary);
  EXPECT_EQ(s.engine.max_iter, 4);
}

template <typename S>
void expect_help_lists(const std::string& job, const std::vector<Param<S>>& declared) {
  // The help with every run of blanks and line breaks as one space: wrapping splits phrases.
  const std::string help =
      std::regex_replace(parse({job, "--help"}).print, std::regex("\\s+"), " ");
  for (const Param<S>& p : declared) {
    if (!(p.fronts & qd::params::kCommand)) continue;
    const std::string option = qd::params::option_name(p.name);
    EXPECT_NE(help.find(option), std::string::npos) << option;
    for (const std::string& a : p.aliases) EXPECT_NE(help.find(a), std::string::npos) << a;
    const bool has_default = p.type == qd::params::Type::Real ||
                             p.type == qd::params::Type::Integer ||
                             p.type == qd::params::Type::Choice;
    if (has_default) {
      EXPECT_NE(help.find("default " + qd::params::value_text(p, p.default_value) + ")"),
                std::string::npos)
          << option;
    }
  }
  for (const char* option : {"--report", "--progress", "--no-progress", "--quiet", "--version",
                             "--help", "--overwrite-input"})
    EXPECT_NE(help.find(option), std::string::npos) << option;
}

TEST(Options, HelpNamesEveryOptionAndItsDefault) {
  expect_help_lists("approximate", qd::params::approximate_params());
  expect_help_lists("segment", qd::params::segment_params());
  expect_help_lists("flatten", qd::params::flatten_params());
  const std::string top = parse({"--help"}).print;
  EXPECT_NE(top.find("Subcommands:"), std::string::npos) << top;
  EXPECT_NE(top.find("--max-iter"), std::string::npos) << top;
}

// Files that cannot be made as asked are refused before anything runs, naming what is missing.
TEST(Options, PatternFilesThatNeedAUnitOrAWidthAreRefused) {
  EXPECT_NE(usage_error({"flatten", "a", "b", "--pdf", "p.pdf"}).find("--unit"), std::string::npos);
  EXPECT_NE(
      usage_error({"flatten", "a", "b", "--dxf", "p.dxf", "--dxf-style", "aama"}).find("--unit"),
      std::string::npos);
  EXPECT_NE(usage_error({"flatten", "a", "b", "--marker-svg", "m.svg"}).find("--marker-width"),
            std::string::npos);
  EXPECT_EQ(
      usage_error({"flatten", "a", "b", "--dxf", "p.dxf", "--dxf-style", "aama", "--unit", "mm"}),
      "");
}

}  // namespace
