// The declarations of every job's parameters (params/): each name is snake_case and unique,
// every command spelling (name and older aliases) belongs to one parameter, the default lies in
// the range, a Choice's default is one of its choices, every parameter has a label and help,
// and a parameter one front end lacks says why.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <set>

#include "approximate_params.h"
#include "flatten_params.h"
#include "param_samples.h"
#include "segment_params.h"

namespace {

using qd::params::ParamInfo;

std::map<std::string, std::vector<ParamInfo>> jobs() {
  return {{"approximate", qd::params::infos(qd::params::approximate_params())},
          {"segment", qd::params::infos(qd::params::segment_params())},
          {"flatten", qd::params::infos(qd::params::flatten_params())}};
}

TEST(Params, EveryDeclarationIsComplete) {
  for (const auto& [job, params] : jobs()) {
    std::set<std::string> names, spellings, labels;
    for (const ParamInfo& p : params) {
      SCOPED_TRACE(job + " " + p.name);
      EXPECT_TRUE(std::regex_match(p.name, std::regex("[a-z][a-z0-9]*(_[a-z0-9]+)*")));
      EXPECT_TRUE(names.insert(p.name).second) << "declared twice";
      EXPECT_TRUE(labels.insert(p.label).second) << "label used twice: " << p.label;
      EXPECT_FALSE(p.help.empty());
      for (const std::string& s :
           {qd::params::option_name(p.name), "--no-" + qd::params::option_name(p.name).substr(2)})
        EXPECT_TRUE(spellings.insert(s).second) << s;
      for (const auto* list : {&p.aliases, &p.off_aliases})
        for (const std::string& a : *list)
          EXPECT_TRUE(spellings.insert(a).second) << "alias " << a << " taken";
      if (p.type == qd::params::Type::Real || p.type == qd::params::Type::Integer) {
        EXPECT_EQ(qd::params::range_violation(p.range, std::get<double>(p.default_value)), "");
      }
      if (p.type == qd::params::Type::Choice) {
        EXPECT_NE(
            std::find(p.choices.begin(), p.choices.end(), std::get<std::string>(p.default_value)),
            p.choices.end());
      }
      EXPECT_EQ(p.fronts == qd::params::kBoth, p.why_not.empty()) << "why_not: " << p.why_not;
      EXPECT_NE(qd::params::test::sample_value(p), p.default_value);
    }
  }
}

// A length's unit is in its name: _ae for AE; model units without a suffix (tolerance_model
// says which of the two tolerances it is).
TEST(Params, LengthsSayTheirUnitInTheirName) {
  for (const auto& [job, params] : jobs())
    for (const ParamInfo& p : params) {
      const bool ae_name = p.name.size() > 3 && p.name.compare(p.name.size() - 3, 3, "_ae") == 0;
      EXPECT_EQ(ae_name, p.unit == qd::params::Unit::AverageEdge) << job << " " << p.name;
      if (p.unit == qd::params::Unit::Degrees) {
        EXPECT_NE(p.name.find("_deg"), std::string::npos) << p.name;
      }
    }
}

TEST(Params, RangesSayWhatAValueMustBe) {
  using qd::params::Range;
  const Range positive{0, std::numeric_limits<double>::infinity(), true, false};
  EXPECT_EQ(qd::params::range_violation(positive, 0), "must be greater than 0");
  EXPECT_EQ(qd::params::range_violation(positive, std::nan("")), "must be a finite number");
  EXPECT_EQ(qd::params::range_violation({0, 1, false, true}, 1), "must be below 1");
  EXPECT_EQ(qd::params::range_violation({0, 1, false, true}, -1), "must not be negative");
  EXPECT_EQ(qd::params::range_violation({1, 9, false, false}, 10), "must be at most 9");
  EXPECT_EQ(qd::params::range_violation({1, 9, false, false}, 0), "must be at least 1");
  EXPECT_EQ(qd::params::range_text({0, 90, true, false}), "0 < x <= 90");
  EXPECT_EQ(qd::params::range_text(positive), "> 0");
}

TEST(Params, PatchToleranceTextReadsAndWritesBack) {
  std::map<int, double> t;
  qd::params::parse_patch_tolerance("3=0.05, 7=2 -1=1e-3", t);
  EXPECT_EQ(t, (std::map<int, double>{{-1, 1e-3}, {3, 0.05}, {7, 2}}));
  EXPECT_EQ(qd::params::patch_tolerance_text(t), "-1=0.001,3=0.05,7=2");
  EXPECT_THROW(qd::params::parse_patch_tolerance("3", t), qd::params::ParamError);
  EXPECT_THROW(qd::params::parse_patch_tolerance("3=-1", t), qd::params::ParamError);
  EXPECT_THROW(qd::params::parse_patch_tolerance("x=1", t), qd::params::ParamError);
}

TEST(Params, EngineParamsPutTheTolerancesInModelUnits) {
  qd::params::ApproximateSettings s;
  s.tolerance_ae = 0.5;
  s.patch_tolerance_ae = {{4, 2.0}};
  qd::approximate::Params p = qd::params::engine_params(s, 0.1, {4, 4, 9});
  EXPECT_DOUBLE_EQ(p.tolerance, 0.05);
  EXPECT_DOUBLE_EQ(p.patch_tolerance.at(4), 0.2);
  s.tolerance_model = 0.3;
  EXPECT_EQ(qd::params::engine_params(s, 0.1, {4}).tolerance, 0.3);
  EXPECT_THROW(qd::params::engine_params(s, 0.1, {9}), qd::params::ParamError);
  EXPECT_NO_THROW(qd::params::engine_params({}, 0.1, {}));
}

TEST(Params, GrainDirectionIsThreeNumbersOrLongest) {
  using qd::params::direction_text;
  using qd::params::parse_direction;
  EXPECT_EQ(parse_direction(" 0, 0.5 ,2"), Eigen::Vector3d(0, 0.5, 2));
  EXPECT_EQ(direction_text(Eigen::Vector3d(0, 0.5, 2)), "0,0.5,2");
  EXPECT_TRUE(parse_direction("longest").isZero());
  EXPECT_EQ(direction_text(Eigen::Vector3d::Zero()), "longest");
  for (const char* bad : {"0,0,0", "1,2", "1,2,3,4", "x,1,2", "1,,2", "", "nan,1,0"})
    EXPECT_THROW(parse_direction(bad), qd::params::ParamError) << bad;
}

}  // namespace
