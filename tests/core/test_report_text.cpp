// The words of the Result's enums (report_text.h) and the engine's neutral naming of a
// parameter's setting (setting_text.h).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "approximate/approximate_log.h"
#include "approximate/report_text.h"

namespace qd {
namespace {

using namespace qd::approximate;
using namespace qd::common;

TEST(ReportText, EveryTermHasItsOwnName) {
  std::set<std::string> names;
  for (Term t : {Term::None, Term::Curve, Term::Defect, Term::Both}) names.insert(term_name(t));
  EXPECT_EQ(names, (std::set<std::string>{"none", "curve", "defect", "both"}));
}

TEST(ReportText, EveryTargetKindHasItsOwnName) {
  std::set<std::string> names;
  for (TargetKind k :
       {TargetKind::Curve, TargetKind::ClosedCurve, TargetKind::Plane, TargetKind::Unchanged})
    names.insert(target_kind_name(k));
  EXPECT_EQ(names, (std::set<std::string>{"curve", "closed curve", "plane", "unchanged"}));
}

// A curve patch far from one developable surface is told to try the angle-defect term, and
// auto only where auto would have measured it (not on a group it does not race).
TEST(ReportText, TheFarFromDevelopableWarningNamesAutoOnlyWhereAutoRaces) {
  PatchReport p;
  p.fitted = true;
  p.target_kind = TargetKind::Curve;
  p.developability = Term::Curve;
  p.fit_residual_deg = 17.5;
  p.developability_reason = TermChoice::AsAsked;
  const std::string asked = patch_log_line(p, 1.0);
  EXPECT_NE(asked.find("warning: fit residual 17.5°"), std::string::npos) << asked;
  EXPECT_NE(asked.find("(developability defect or auto)"), std::string::npos) << asked;
  p.developability_reason = TermChoice::AutoNotRaced;
  const std::string not_raced = patch_log_line(p, 1.0);
  EXPECT_NE(not_raced.find("warning: fit residual 17.5°"), std::string::npos) << not_raced;
  EXPECT_EQ(not_raced.find("or auto"), std::string::npos) << not_raced;
  EXPECT_NE(not_raced.find("developability defect; auto does not race it"), std::string::npos)
      << not_raced;
  p.fit_residual_deg = 5.0;
  EXPECT_EQ(patch_log_line(p, 1.0).find("warning"), std::string::npos);
}

TEST(ReportText, EveryTermChoiceHasText) {
  std::set<std::string> texts;
  for (TermChoice c :
       {TermChoice::AsAsked, TermChoice::Planar, TermChoice::TooSmall, TermChoice::NoCurveFits,
        TermChoice::EarlierPass, TermChoice::AutoNoCurveFits, TermChoice::AutoNotRaced,
        TermChoice::AutoAfterCurve, TermChoice::Auto, TermChoice::AutoMeasured}) {
    PatchReport p;
    p.developability_reason = c;
    p.candidates = {{Term::Curve, 4, 50.0, 0.1, true, false}};
    texts.insert(term_choice_text(p));
  }
  EXPECT_EQ(texts.size(), 10u);
  EXPECT_EQ(texts.count(""), 0u);
}

TEST(ReportText, MeasuredChoiceNamesEveryCandidate) {
  PatchReport p;
  p.developability_reason = TermChoice::AutoMeasured;
  p.candidates = {{Term::Curve, 4, 50.0, 0.1, false, true},
                  {Term::Both, 6, 70.0, 0.1, true, false}};
  const std::string text = term_choice_text(p);
  EXPECT_EQ(text.rfind("auto, measured:", 0), 0u) << text;
  EXPECT_NE(text.find("curve"), std::string::npos) << text;
  EXPECT_NE(text.find("both"), std::string::npos) << text;
  EXPECT_NE(text.find("(kept)"), std::string::npos) << text;
}

TEST(ReportText, StrongerRowsSayWhyTheyWereKeptOrStopped) {
  PatchReport p;
  p.developability_reason = TermChoice::AutoMeasured;
  const auto text = [&](double removed, bool kept, bool dropped, bool further = false) {
    p.candidates = {{Term::Curve, 4, 50.0, 0.1, !kept, false},
                    {Term::Defect, 3, removed, 0.05, kept, dropped, NotRun::No, 100, further}};
    return term_choice_text(p);
  };
  EXPECT_NE(text(90, true, false).find("defect ×100 weight −90.0% in 3 it. (kept: less G_ABD left"),
            std::string::npos)
      << text(90, true, false);
  EXPECT_NE(text(0, false, true).find("(stopped: removed nothing)"), std::string::npos);
  EXPECT_NE(text(20, false, true, true).find("(stopped: moved further than the pick)"),
            std::string::npos);
  EXPECT_NE(text(20, false, false).find("(not kept: left more G_ABD than the pick)"),
            std::string::npos);
  EXPECT_NE(text(20, false, false).find("curve −50.0% in 4 it. (kept)"), std::string::npos);
  // Passed the bar, but another weight left less and was kept.
  p.candidates = {{Term::Curve, 4, 50.0, 0.1, false, false},
                  {Term::Defect, 3, 80.0, 0.05, false, false, NotRun::No, 100, false},
                  {Term::Defect, 9, 95.0, 0.04, true, false, NotRun::No, 30, false}};
  p.candidates[1].outdone_by = 30;
  const std::string ladder = term_choice_text(p);
  EXPECT_NE(ladder.find("defect ×100 weight −80.0% in 3 it. (passed, but defect ×30 weight left "
                        "less), defect ×30 weight −95.0% in 9 it. (kept: less G_ABD left"),
            std::string::npos)
      << ladder;
}

// After a pick of the rows the stronger rows answer to the candidate whose move bounds them and
// to half the pick's G_ABD (group_run.h), and say so.
TEST(ReportText, StrongerRowsAfterThePickOfTheRowsNameTheirBound) {
  PatchReport p;
  p.developability_reason = TermChoice::AutoMeasured;
  const auto text = [&](bool kept, bool dropped, bool further, bool short_pace) {
    CandidateReport stronger{Term::Defect, 12, 92.0, 0.05, kept, dropped, NotRun::No, 100, further};
    stronger.fell_short = short_pace;
    stronger.bounded_by = Term::Both;
    p.candidates = {{Term::Defect, 20, 60.0, 0.01, !kept, false},
                    {Term::Both, 9, 40.0, 0.2, false, true},
                    stronger};
    return term_choice_text(p);
  };
  EXPECT_NE(text(true, false, false, false)
                .find("(kept: half the pick's G_ABD left or less, moved less than both)"),
            std::string::npos)
      << text(true, false, false, false);
  EXPECT_NE(text(false, true, true, false).find("(stopped: moved further than both)"),
            std::string::npos);
  EXPECT_NE(
      text(false, true, false, true).find("(stopped: its pace would not halve the pick's G_ABD)"),
      std::string::npos);
  EXPECT_NE(text(false, true, false, false).find("(stopped: removed nothing)"), std::string::npos);
  EXPECT_NE(text(false, false, false, false).find("(not kept: left more than half the pick's"),
            std::string::npos);
  EXPECT_EQ(text(false, true, true, false).find("than the pick"), std::string::npos);
}

// After the rows' plateau only the tolerance bounds the stronger rows and no pace stops them
// (group_run.h): the log names the plateau or the tolerance, never a candidate or a pace.
TEST(ReportText, StrongerRowsAfterTheRowsPlateauSaySo) {
  PatchReport p;
  p.developability_reason = TermChoice::AutoMeasured;
  const auto text = [&](bool kept, bool dropped, bool further = false, bool stalled = false) {
    CandidateReport stronger{Term::Defect, 30, 98.8, 0.01, kept, dropped, NotRun::No, 100, further};
    stronger.after_plateau = true;
    stronger.fell_short = stalled;
    p.candidates = {{Term::Curve, 2, 0.0, 0.0, false, true},
                    {Term::Defect, 27, 27.5, 0.001, !kept, false},
                    stronger};
    return term_choice_text(p);
  };
  EXPECT_NE(text(true, false)
                .find("defect ×100 weight −98.8% in 30 it. (kept: half the pick's "
                      "G_ABD left or less, after its plateau)"),
            std::string::npos)
      << text(true, false);
  EXPECT_NE(text(false, false).find("(not kept: left more than half the pick's G_ABD)"),
            std::string::npos);
  EXPECT_NE(text(false, true).find("(stopped: removed nothing)"), std::string::npos);
  EXPECT_NE(text(false, true, true).find("(stopped: moved further than the tolerance)"),
            std::string::npos);
  EXPECT_NE(text(false, true, false, true)
                .find("(stopped: more than half the pick's G_ABD left at their plateau)"),
            std::string::npos);
  for (const std::string& t :
       {text(true, false), text(false, false), text(false, true), text(false, true, false, true)}) {
    EXPECT_EQ(t.find("moved further"), std::string::npos) << t;
    EXPECT_EQ(t.find("moved less"), std::string::npos) << t;
    EXPECT_EQ(t.find("pace"), std::string::npos) << t;
  }
}

TEST(ReportText, ALateCandidateSaysItStartedWhenTheLeaderStopped) {
  PatchReport p;
  p.developability_reason = TermChoice::AutoMeasured;
  const auto text = [&](bool kept) {
    p.candidates = {{Term::Curve, 2, 0.0, 0.0, false, true},
                    {Term::Defect, 8, 40.0, 0.1, !kept, false},
                    {Term::Both, 5, kept ? 60.0 : 0.0, 0.3, kept, !kept}};
    p.candidates.back().late = true;
    return term_choice_text(p);
  };
  EXPECT_NE(text(true).find("both −60.0% in 5 it. (started when the leader stopped; kept)"),
            std::string::npos)
      << text(true);
  EXPECT_NE(text(false).find("(started when the leader stopped; left after the trial)"),
            std::string::npos)
      << text(false);
  EXPECT_EQ(text(false).find("not run"), std::string::npos) << text(false);
}

// Candidates that never started say how many steps of the first candidate left little.
TEST(ReportText, CandidatesNotRunSayHowManyStepsOfTheFirstLeftLittle) {
  PatchReport p;
  p.developability_reason = TermChoice::AutoMeasured;
  const auto text = [&](NotRun why) {
    p.candidates = {{Term::Curve, 9, 99.9, 0.1, true, false},
                    {Term::Defect, 0, 0.0, 0.0, false, true},
                    {Term::Both, 0, 0.0, 0.0, false, true}};
    p.candidates[1].not_run = p.candidates[2].not_run = why;
    return term_choice_text(p);
  };
  EXPECT_NE(text(NotRun::LeftLittle)
                .find("defect and both not run: the first step of curve left less than δ_ABD"),
            std::string::npos)
      << text(NotRun::LeftLittle);
  EXPECT_NE(text(NotRun::LeftLittleInTwo)
                .find("defect and both not run: the first two steps of curve left less than δ_ABD"),
            std::string::npos)
      << text(NotRun::LeftLittleInTwo);
}

TEST(ReportText, StopsOfSeveralPassesNameEachPassInOrder) {
  std::vector<PassStop> stops(3);
  stops[0].pass = SolvePass::AllAtOnce;
  stops[1].pass = SolvePass::SeamsHeld;
  stops[1].reason = PatchStop::RatioAbd;
  stops[2].pass = SolvePass::SeamsFree;
  stops[2].reason = PatchStop::Unfitted;
  stops[2].detail = "too few faces";
  const std::string text = stop_reason_text(stops);
  const size_t all = text.find(pass_name(SolvePass::AllAtOnce));
  const size_t held = text.find(pass_name(SolvePass::SeamsHeld));
  const size_t free = text.find(pass_name(SolvePass::SeamsFree));
  ASSERT_NE(free, std::string::npos) << text;
  EXPECT_LT(all, held);
  EXPECT_LT(held, free);
  EXPECT_NE(text.find("too few faces"), std::string::npos) << text;
  EXPECT_EQ(stop_reason_text({PassStop{}}), "maxIter reached");  // the only pass is not named
}

TEST(ReportText, EveryStopHasText) {
  for (PatchStop s :
       {PatchStop::MaxIter, PatchStop::Plateau, PatchStop::RatioAbd, PatchStop::RatioObd,
        PatchStop::NoStep, PatchStop::Planar, PatchStop::Unfitted}) {
    PassStop stop;
    stop.reason = s;
    EXPECT_FALSE(pass_stop_text(stop).empty());
  }
}

// The segment-first note names its parameter as the front end spells it, and by its declared
// name without one: never as a command-line option.
TEST(SettingText, EngineNamesNoCommandOption) {
  const std::string neutral = segmented_note("it is closed", 4, {});
  EXPECT_EQ(neutral.find("--"), std::string::npos) << neutral;
  EXPECT_NE(neutral.find("segment_first = never"), std::string::npos) << neutral;
  const std::string spelt =
      segmented_note("it is closed", 4, [](const std::string& name, const std::string& value) {
        return "<" + name + ":" + value + ">";
      });
  EXPECT_NE(spelt.find("<segment_first:never>"), std::string::npos) << spelt;
}

}  // namespace
}  // namespace qd
