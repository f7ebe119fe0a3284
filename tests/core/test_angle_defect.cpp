// The angle-defect developability term (angle_defect.h, issue 11): its linearisation, and what
// the engine does with it on wrinkled patches, where the paper's curve targets cannot help.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "approximate/angle_defect.h"
#include "approximate/deformer.h"
#include "approximate/group_mesh.h"
#include "approximate/group_run.h"
#include "approximate/quasidev.h"
#include "approximate/report_text.h"
#include "approximate/term_race.h"
#include "approximate/validate.h"
#include "common/error.h"
#include "common/format_text.h"
#include "test_meshes.h"

namespace qd {
namespace {

using namespace qd::approximate;
using namespace qd::common;

// A square sheet (n×n quads, side 2) wrinkled by bumps and dents of both signs: doubly curved
// everywhere, so its Gauss image is a 2-D blob and no curve fits it. Split into `patches`
// vertical strips.
Problem wrinkled_sheet(int n = 24, double amplitude = 0.08, int patches = 1) {
  Problem p;
  p.V.resize((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = 2.0 * i / n - 1, y = 2.0 * j / n - 1;
      const double z =
          amplitude * (std::sin(3.1 * x) * std::cos(2.3 * y) + 0.6 * std::sin(4.7 * x * y));
      p.V.row(j * (n + 1) + i) << x, y, z;
    }
  p.F.resize(2 * n * n, 3);
  int f = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      p.F.row(f++) << a, b, d;
      p.F.row(f++) << a, d, c;
      p.patch.push_back(i * patches / n);
      p.patch.push_back(i * patches / n);
    }
  if (patches == 1) p.patch.clear();
  p.params.tolerance = 0.1;
  return p;
}

// The whole mesh of p as one group, and its defect rows on every free interior vertex.
struct OneGroup {
  GroupMesh g;
  VertexFaces incident;
  DefectStars rows;
  explicit OneGroup(const Problem& p) : g(group(p)), incident(g.F, g.V0.rows()) {
    std::vector<char> has_row(g.fixed.size(), 0);
    for (int v : g.owned) has_row[static_cast<size_t>(v)] = !g.fixed[static_cast<size_t>(v)];
    rows = defect_stars(g, incident, has_row, 1.0);
  }
  static GroupMesh group(const Problem& p) {
    const Topology topo = validate(p);
    const VertexRoles roles = vertex_roles(p, topo, p.params.seams);
    std::vector<int> faces(static_cast<size_t>(p.F.rows()));
    for (size_t f = 0; f < faces.size(); ++f) faces[f] = static_cast<int>(f);
    return extract_group(p.V, p.F, faces, std::vector<int>(faces.size(), 0), roles.constrained,
                         roles.interior, VertexFaces(p.F, p.V.rows()), p.params);
  }
};

// The rows of s linearised at X, with X's angles as the engine passes them.
DefectLinearisation linearised(const OneGroup& s, const Positions& X) {
  return linearise_defects(s.rows, s.g, s.incident, X, vertex_angles(X, s.g.F));
}

TEST(AngleDefect, GradientMatchesFiniteDifferences) {
  const OneGroup s(wrinkled_sheet(8));
  ASSERT_FALSE(s.rows.empty());
  const DefectLinearisation lin = linearised(s, s.g.V0);
  const double h = 1e-6;
  double worst = 0;
  for (size_t r = 0; r < s.rows.vertex.size(); r += 5)
    for (int i = s.rows.start[r]; i < s.rows.start[r + 1]; ++i)
      for (int d = 0; d < 3; ++d) {
        Positions plus = s.g.V0, minus = s.g.V0;
        plus(s.rows.star[static_cast<size_t>(i)], d) += h;
        minus(s.rows.star[static_cast<size_t>(i)], d) -= h;
        const double numeric =
            (linearised(s, plus).defect[r] - linearised(s, minus).defect[r]) / (2 * h);
        worst = std::max(worst, std::abs(numeric - lin.gradient[static_cast<size_t>(i)](d)));
      }
  EXPECT_LT(worst, 1e-6);
}

TEST(AngleDefect, DefectIsTwoPiMinusTheAngleSum) {
  const OneGroup s(wrinkled_sheet(6));
  const DefectLinearisation lin = linearised(s, s.g.V0);
  Problem flat = wrinkled_sheet(6, 0.0);
  const OneGroup f(flat);
  const DefectLinearisation zero = linearised(f, f.g.V0);
  for (double k : zero.defect) EXPECT_NEAR(k, 0.0, 1e-12);  // a flat sheet is developable
  double largest = 0;
  for (double k : lin.defect) largest = std::max(largest, std::abs(k));
  EXPECT_GT(largest, 1e-3);  // the wrinkled one is not
}

TEST(AngleDefect, WrinkledSheetLosesMostCurvatureWhereTheCurveCannotHelp) {
  Problem p = wrinkled_sheet();
  p.params.tolerance = 1.0;
  p.params.defect_weight = 1.0;
  Problem q = p;
  q.params.developability = Developability::Curve;
  const Result curve = approximate::approximate(q);
  p.params.developability = Developability::Defect;
  const Result r = approximate::approximate(p);
  ASSERT_EQ(r.patches.size(), 1u);
  EXPECT_EQ(r.patches[0].developability, Term::Defect);
  EXPECT_GT(r.abd_reduction, 60.0);
  EXPECT_GT(r.abd_reduction, curve.abd_reduction + 30.0);
  EXPECT_EQ(flipped_faces(p.F, p.V, r.V), 0);
  // The open boundary is kept (default): bit for bit.
  const int n = 24;
  for (int i = 0; i <= n; ++i)
    for (int v : {i, n * (n + 1) + i, i * (n + 1), i * (n + 1) + n})
      EXPECT_EQ(r.V.row(v), p.V.row(v));
}

TEST(AngleDefect, AutoTakesDefectRowsWhereNoCurveFitsAndSaysWhy) {
  Problem p = wrinkled_sheet(24, 0.2);  // its normals fill the sphere
  p.params.tolerance = 1.0;
  p.params.segment_first = SegmentFirst::Never;  // kept one patch
  Problem curve = p;
  curve.params.developability = Developability::Curve;
  EXPECT_THROW(approximate::approximate(curve),
               Error);  // the paper cannot fit it: refused, as before
  const Result r = approximate::approximate(p);
  EXPECT_EQ(r.patches[0].developability, Term::Defect);
  EXPECT_NE(term_choice_text(r.patches[0]).find("no Gauss-image curve fits"), std::string::npos);
  EXPECT_GT(r.abd_reduction, 1.0);
  EXPECT_EQ(flipped_faces(p.F, p.V, r.V), 0);
}

// Auto races the candidate terms and keeps the one that removes most G_ABD: its result is
// exactly that term's own run, and no candidate removes more.
TEST(AngleDefect, AutoKeepsTheCandidateThatRemovesMost) {
  Problem p = test::bumpy_cylinder(48, 24, 0.08);
  p.params.tolerance = 0.2;
  const Result r = approximate::approximate(p);
  const PatchReport& patch = r.patches[0];
  // The three terms, and the stronger rows after them where the pick has curve targets.
  ASSERT_GE(patch.candidates.size(), 3u) << term_choice_text(patch);
  int kept = 0;
  for (const CandidateReport& c : patch.candidates) {
    kept += c.kept;
    EXPECT_TRUE(c.started()) << term_name(c.term);  // the curve's first step leaves much
    EXPECT_NE(term_choice_text(patch).find(term_name(c.term)), std::string::npos);
  }
  EXPECT_EQ(kept, 1);
  const bool stronger_kept =  // (its own test below)
      std::any_of(patch.candidates.begin(), patch.candidates.end(),
                  [](const CandidateReport& c) { return c.weight_factor != 1 && c.kept; });
  for (const auto& [mode, name] : {std::pair{Developability::Curve, Term::Curve},
                                   std::pair{Developability::Defect, Term::Defect},
                                   std::pair{Developability::Both, Term::Both}}) {
    Problem alone = p;
    alone.params.developability = mode;
    const Result single = approximate::approximate(alone);
    // The kept run is that term's own, unless the race fitted its curve again (term_race.h).
    if (patch.developability == name && !patch.stops[0].refit_behind && !stronger_kept) {
      EXPECT_EQ(r.V, single.V) << term_name(name);
    }
    EXPECT_GE(r.abd_reduction, single.abd_reduction - 2.0)
        << term_name(name) << ": percentage points";
  }
}

// Once the leader has left less than δ_ABD of the start's G_ABD, no other candidate can remove a
// meaningful share more: the race stops them there rather than at the keep-the-leader round
// (0.4 maxIter), and keeps the leader.
TEST(AngleDefect, AutoStopsTheRaceWhenTheLeaderLeavesLessThanDeltaAbd) {
  Problem p = test::bumpy_plane(48, 0.05);
  const Result r = approximate::approximate(p);
  const PatchReport& patch = r.patches[0];
  ASSERT_EQ(patch.candidates.size(), 3u);
  const int keep_leader_round = static_cast<int>(std::lround(kKeepLeaderShare * p.params.max_iter));
  for (const CandidateReport& c : patch.candidates) {
    if (c.kept) {
      EXPECT_GE(c.abd_reduction, 100 - p.params.stop_abd);
    } else {
      EXPECT_TRUE(c.dropped) << term_name(c.term);
      EXPECT_LT(c.iterations, keep_leader_round) << term_name(c.term);
    }
  }
}

// The race begins with the curve term's first step alone: where that leaves less than δ_ABD of
// the start's G_ABD, the other terms never start, and auto costs what the curve term alone does
// (the same result, the same factorisations); the log says why they did not run.
TEST(AngleDefect, AutoStartsNoOtherTermWhereTheCurveTermsFirstStepLeavesLessThanDeltaAbd) {
  Problem p = test::bumpy_plane(48, 0.05);
  p.params.threads = 1;
  Problem curve = p;
  curve.params.developability = Developability::Curve;
  const Result alone = approximate::approximate(curve);
  ASSERT_FALSE(alone.patches[0].history.empty());
  const double g0 = alone.patches[0].before.g_abd;
  ASSERT_LE(alone.patches[0].history.front().figures.g_abd, p.params.stop_abd / 100 * g0);
  const Result r = approximate::approximate(p);
  const PatchReport& patch = r.patches[0];
  ASSERT_EQ(patch.candidates.size(), 3u);
  for (const CandidateReport& c : patch.candidates) {
    EXPECT_EQ(c.started(), c.term == Term::Curve) << term_name(c.term);
    EXPECT_EQ(c.kept, c.term == Term::Curve) << term_name(c.term);
    if (!c.started()) {
      EXPECT_EQ(c.iterations, 0) << term_name(c.term);
    }
  }
  EXPECT_EQ(r.V, alone.V);
  EXPECT_EQ(r.factorizations, alone.factorizations);
  EXPECT_NE(term_choice_text(patch).find("defect and both not run: the first step of curve"),
            std::string::npos)
      << term_choice_text(patch);
}

// A candidate that has removed nothing after kNothingRounds iterations, while the leader has
// removed something, stops there (before the drop-the-worst round of kDropWorstShare maxIter).
TEST(AngleDefect, AutoStopsACandidateThatRemovesNothing) {
  Problem p = wrinkled_sheet(24, 0.08);  // the curve targets and both remove nothing there
  p.params.tolerance = 1.0;
  p.params.segment_first = SegmentFirst::Never;
  const Result r = approximate::approximate(p);
  const PatchReport& patch = r.patches[0];
  ASSERT_GE(patch.candidates.size(), 3u);  // and the stronger rows, where they ran
  bool nothing = false;
  for (const CandidateReport& c : patch.candidates) {
    if (c.abd_reduction > 0) continue;
    nothing = true;
    EXPECT_TRUE(c.dropped) << term_name(c.term);
    EXPECT_LE(c.iterations, kNothingRounds) << term_name(c.term);
  }
  EXPECT_TRUE(nothing);
  EXPECT_LT(kNothingRounds, std::lround(kDropWorstShare * p.params.max_iter));
}

// Both, the angle-defect rows with the curve targets, does not start with them where those
// targets' first step removed nothing and the rows' first step removed some: where the rows then
// run to maxIter it never starts, the log says why, and the patch keeps a run of the others,
// exactly as that term alone gives it. Where the rows stop short of maxIter it starts then, from
// the same start, is judged by its own steps, and the log says it started late (here its first
// kNothingRounds steps remove nothing; the race fits its curve again rather than drop it, as its
// own stop rule would at that stall, and it ends with less G_ABD than the rows).
TEST(AngleDefect, AutoStartsBothOnlyWhenTheRowsStopShortWhereTheTargetsFirstStepRemovesNothing) {
  Problem p = wrinkled_sheet(24, 0.08);
  p.params.tolerance = 1.0;
  p.params.segment_first = SegmentFirst::Never;
  const auto alone = [&](Developability term, int max_iter) {
    Problem q = p;
    q.params.developability = term;
    q.params.max_iter = max_iter;
    return approximate::approximate(q);
  };
  ASSERT_LE(alone(Developability::Curve, 1).abd_reduction, 0.0);  // its first step: nothing
  ASSERT_GT(alone(Developability::Defect, 1).abd_reduction, 0.0);
  const Result rows = alone(Developability::Defect, p.params.max_iter);
  const PassStop stop = rows.patches[0].stops.back();
  ASSERT_EQ(stop.reason, PatchStop::Plateau);  // short of maxIter
  const int short_iter = stop.iterations_run;
  for (const int max_iter : {short_iter - 1, p.params.max_iter}) {
    Problem q = p;
    q.params.max_iter = max_iter;
    const Result r = approximate::approximate(q);
    const PatchReport& patch = r.patches[0];
    const bool late = max_iter == p.params.max_iter;  // the rows stop before maxIter
    // Where the rows win, no stronger rows run after them (group_run.h).
    ASSERT_GE(patch.candidates.size(), 3u);
    if (!late) {
      ASSERT_EQ(patch.candidates.size(), 3u);
    }
    for (size_t k = 0; k < 3; ++k) {
      const CandidateReport& c = patch.candidates[k];
      EXPECT_EQ(c.started(), late || c.term != Term::Both) << term_name(c.term);
      EXPECT_EQ(c.late, late && c.term == Term::Both) << term_name(c.term);
      if (c.term == Term::Both) {
        EXPECT_EQ(c.not_run, late ? NotRun::No : NotRun::TargetsRemovedNothing);
        if (late) {
          EXPECT_GT(c.iterations, kNothingRounds);
          EXPECT_GT(c.abd_reduction, patch.candidates[1].abd_reduction);  // beyond the rows
        } else {
          EXPECT_EQ(c.iterations, 0);
          EXPECT_FALSE(c.kept);
        }
      }
    }
    const std::string text = term_choice_text(patch);
    EXPECT_EQ(
        text.find("both not run: the first step of curve removed nothing") != std::string::npos,
        !late)
        << text;
    EXPECT_EQ(text.find("(started when the leader stopped") != std::string::npos, late) << text;
    const Result rows_alone = alone(Developability::Defect, max_iter);
    if (late) {
      EXPECT_LT(r.patches[0].after.g_abd, rows_alone.patches[0].after.g_abd) << text;
    } else {
      EXPECT_EQ(patch.developability, Term::Defect) << text;
      EXPECT_EQ(r.V, rows_alone.V);
    }
  }
}

TEST(AngleDefect, AutoKeepsStrongerRowsWhereTheyLeaveLessAndMoveLess) {
  // A smooth bumpy cylinder whose vertices slid within it: no edge follows a ruling, so the
  // curve targets' face normals are out of reach, and the pick's result moves further than the
  // angle-defect rows need to at a stronger weight (group_run.h). Every weight runs, and the
  // one that leaves least is kept.
  Problem p = test::irregular_cylinder(48, 16, 0.08, 0.2);
  p.params.segment_first = SegmentFirst::Never;
  const Result r = approximate::approximate(p);
  const PatchReport& patch = r.patches[0];
  const auto first_rung =
      std::find_if(patch.candidates.begin(), patch.candidates.end(),
                   [](const CandidateReport& c) { return c.weight_factor != 1; });
  const auto stronger =
      std::find_if(patch.candidates.begin(), patch.candidates.end(),
                   [](const CandidateReport& c) { return c.weight_factor != 1 && c.kept; });
  ASSERT_NE(stronger, patch.candidates.end()) << term_choice_text(patch);
  EXPECT_EQ(patch.candidates.end() - first_rung,
            static_cast<std::ptrdiff_t>(std::size(kStrongerRowsFactors)));
  for (const CandidateReport& c : patch.candidates)
    if (&c != &*stronger && c.started()) {
      EXPECT_FALSE(c.kept) << term_name(c.term);
      if (c.weight_factor == 1)
        EXPECT_GT(stronger->abd_reduction, c.abd_reduction);
      else
        EXPECT_GE(stronger->abd_reduction, c.abd_reduction) << c.weight_factor;
    }
  const auto pick = std::max_element(  // the race's: least G_ABD left
      patch.candidates.begin(), first_rung, [](const CandidateReport& a, const CandidateReport& b) {
        return a.abd_reduction < b.abd_reduction;
      });
  EXPECT_LE(stronger->mean_disp, pick->mean_disp);
  const std::string text = term_choice_text(patch);
  EXPECT_NE(text.find(format_text("defect ×%g weight", stronger->weight_factor) + " −"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("(kept: less G_ABD left, moved less)"), std::string::npos) << text;
  Problem alone = p;  // exactly the kept rows' own run
  alone.params.developability = Developability::Defect;
  alone.params.defect_weight *= stronger->weight_factor;
  EXPECT_EQ(r.V, approximate::approximate(alone).V);
}

TEST(AngleDefect, DefectModeIsScaleAndRotationInvariant) {
  Problem p = wrinkled_sheet(16);
  p.params.developability = Developability::Defect;
  const Result r = approximate::approximate(p);
  const double s = 250.0;
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(1.1, Eigen::Vector3d(3, -1, 2).normalized()).toRotationMatrix();
  Problem q = p;
  q.V = (s * p.V * R.transpose()).eval();
  q.params.tolerance = s * p.params.tolerance;
  const Result rq = approximate::approximate(q);
  const Positions expected = s * r.V * R.transpose();
  EXPECT_LT((rq.V - expected).cwiseAbs().maxCoeff(), 1e-6 * s);
  EXPECT_NEAR(rq.abd_reduction, r.abd_reduction, 1e-6);
}

TEST(AngleDefect, FixedSeamsDoNotMoveAndFreeSeamsStayShared) {
  Problem p = wrinkled_sheet(24, 0.08, 3);
  p.params.tolerance = 1.0;
  p.params.defect_weight = 1.0;
  p.params.developability = Developability::Defect;
  const Result fixed = approximate::approximate(p);
  const int n = 24;
  for (int j = 0; j <= n; ++j)  // seam columns between the strips: i = 8 and 16
    for (int i : {8, 16}) EXPECT_EQ(fixed.V.row(j * (n + 1) + i), p.V.row(j * (n + 1) + i));
  EXPECT_GT(fixed.abd_reduction, 20.0);
  p.params.seams = SeamMode::Free;
  const Result free = approximate::approximate(p);
  EXPECT_GT(free.abd_reduction, 20.0);
  EXPECT_EQ(flipped_faces(p.F, p.V, free.V), 0);
  bool seam_moved = false;
  for (int j = 1; j < n; ++j)
    seam_moved = seam_moved || free.V.row(j * (n + 1) + 8) != p.V.row(j * (n + 1) + 8);
  EXPECT_TRUE(seam_moved);
}

}  // namespace
}  // namespace qd
