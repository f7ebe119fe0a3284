// Developability::Auto decides by measuring (beyond the paper). Each candidate term (the paper's
// curve targets, the angle-defect rows, both) runs from the same start under the same tolerance,
// one iteration each in turn, by successive halving over a fixed share of the iteration budget.
// Round 1 begins with the first candidate alone (the curve term, whose step costs least): where
// that step leaves less than δ_ABD of the start's G_ABD, the others could remove no meaningful
// share more (the last rule below) and never start (on the plane with bumps of 0.5 AE, 12k faces,
// one angle-defect factorisation of each other term cost more than the curve term's whole run by
// CG: 152 → 65 ms, the same result). Where the share it left, left once more, would be less than
// δ_ABD, it takes its step of round 2 alone too, and where that leaves less than δ_ABD the others
// never start either (the irregular plane with bumps of 1 AE, 0.16 wide, 12k faces: its first step
// leaves 1.5 %, its second 0.01 %; 6 → 2 factorisations, 344 → 85 ms, the same result). Where its
// first step removed nothing, the angle-defect rows step next, alone too, and both, the rows with
// the curve targets, does not start where the rows' first step removed some: adding targets that
// only raised G_ABD to rows that lower it never won on the robustness sweep, and on the draped
// garments' panels, whose Gauss images fit no curve within 18–27°, its first iteration cost the
// shared 4-panel tee 14 % of its engine time at 5 iterations. It starts later instead, where the
// rows stop by their own rule (the late start below). Where neither removed anything, both still
// runs (on the spot cut into patches, at --defect-weight 0.3, it alone removes 26 %); elsewhere the
// rows and both step at once, on an idle thread where there is one. While the leader (least G_ABD;
// ties: least mean displacement) still runs: after kNothingRounds rounds any candidate that has
// removed nothing stops, once the leader has removed δ_ABD of the start's G_ABD (the curve targets
// on draped garments: a third round of theirs took the shared 4-panel tee from 99 to 109 ms,
// medians of 11 runs at the default maxIter, same result; a lead of less than δ_ABD is none: at
// --defect-weight 3 the angle-defect rows remove nothing in their first two rounds on the tee's
// front, where both lead with 0.2 %, and then 59 %); after kDropWorstShare of maxIter rounds the
// candidate with most G_ABD left stops, unless the never-worse rule refused its last full step
// (shortened it, or solved it again at weaker weights): its rank then comes from steps it was not
// allowed to take, not from its pace, and no candidate stops for its rank (on the cone with bumps
// of 2 AE, 0.16 wide, 3k faces, both trailed at round 3 with 57 % on a halved step, backed off its
// weights at 7 and ends at 93.1 % against the curve term's 89.4 %; over the robustness sweeps 3
// members gain 2.8–8.4 points, none loses, for 4 % more factorisations. Steps solved again at
// weaker weights count since stop 66: the seed-5 lampshade with bumps of 1.8 AE, 0.1 wide, 76.9 →
// 79.1 % (the curve term, as alone), two members gain, one loses 0.9 point and keeps what its term
// gives alone: docs/robustness.md); and from then on so does any that has removed less than
// kFarBehind of what the leader removed; after kKeepLeaderShare the others stop, but for any whose
// best G_ABD, falling on at its pace over the last kPlateauIterations iterations, would end below
// the leader's likewise projected (a term whose re-fitted targets took hold late: on the cylinder
// with bumps of 2 AE, 0.16 wide, both reaches 87 % against the leader's 79 %, yet trailed it at
// round 12), and the leader runs to its own stop. A pace is judged, here and at a rejoin below,
// only over iterations of one phase of a candidate's run, as the plateau rule of deformer.h
// judges it: one that began a phase (re-fitted targets, moved anchors) fewer than
// kPlateauIterations iterations ago runs on through those (the lampshade with bumps of 2 AE, 0.16
// wide, 12k faces: both's targets are re-fitted after round 13 and its anchors move after round
// 16, and the steps between raise G_ABD; dropped at round 13, and judged out by those steps when
// it rejoined, it left auto the curve term's 89 %; it now reaches 97 %, for 0.8 % more
// factorisations over the robustness sweeps). Where these rules would drop the curve term after
// kPlateauIterations rounds or more, its curve is fitted again instead
// (TargetMode::ReprojectThenRefit, once, where maxIter leaves its new targets kPlateauIterations
// rounds), and the rules spare it for those rounds (on the plane with bumps of 4 AE, 0.16 wide, its
// first targets raise G_ABD, and re-fitted they remove 99.6 % against the leader's 71 %; re-fitting
// both too cost the shirt's re-cuts up to half more time for the same figures). A leader that has
// stopped by its own rule is final, and the others run on until one overtakes it or they stop: a
// term that starts slowly is not dropped for being behind a lead that can grow no more. If that
// leader stopped before maxIter with more than δ_ABD of the start's G_ABD left, the candidates the
// trial dropped while they still ran, and that had removed some, rejoin once, and are judged by the
// steps they take from there: after kPlateauIterations of them they run on while their pace over
// those would take them below the leader by maxIter (the tangent developable with bumps of 1 AE,
// 0.16 wide, 12k faces: the angle-defect rows, dropped at round 3 with 37 %, rejoin when both stops
// at 48 %, and reach 53 %); one with curve targets that these steps would drop (they removed
// nothing, or their pace falls short) has its curve fitted again instead, once, where its own
// iterations leave the new targets kPlateauIterations, since its stop rule would do so at the
// stall that slows it (the irregular cylinder with bumps of 2 AE, 0.08 wide, cells slid by 0.1:
// both, dropped at 84 % where the curve term stopped at 86 %, now reaches 89 %; over the
// robustness sweeps 2 members gain 1.8 and 3.0 points, none loses, for 1.5 % more
// factorisations). Judged by their pace where they were dropped, as before stop 50,
// those that start slowly again after a re-fit stayed out: on the irregular cylinder with bumps of
// 2 AE, 0.08 wide, and two irregular lampshades, 3k faces, both now rejoins and removes 86, 80 and
// 55 % where the leader stopped at 76, 74 and 52 % (over the irregular sweep 2 % more
// factorisations; the shirt at the default maxIter 5 %, the same result). Both, if it never
// started, starts then from the same start, and is dropped once kNothingRounds of its steps removed
// nothing or kPlateauIterations of them give a pace that would not take it below the leader (on
// irregular triangulations of the sweep's lampshades and cones it removes 17–74 % where the rows
// stopped at 10–61 %; on the shared garments at the default maxIter, where it never wins, 4–7 %
// more factorisations). Once the leader has left less than δ_ABD of the start's G_ABD (the share
// the plateau rule calls meaningful), no other can remove a meaningful share more, and the others
// stop (on smooth bumps the curve targets remove all but 1 % within a few iterations, while the
// angle-defect rows, whose factorisation costs several times more, would run on). A candidate that
// stops by its own rule stays in the comparison where it stopped. On the generated family of
// scripts/robustness_sweep.py this keeps the term that running every candidate to its end would
// keep, on all but a few members, at a fraction of the cost (docs/robustness.md has the figures);
// the round counts are not fitted to any one mesh.
#pragma once

#include <functional>
#include <vector>

#include "approximate/deformer.h"
#include "approximate/patch_fit.h"
#include "common/idle_threads.h"

namespace qd::approximate {

constexpr int kNothingRounds = 2;         // or after kDropWorstShare of maxIter, if sooner
constexpr double kDropWorstShare = 0.1;   // at the default maxIter of 30: after 3 rounds
constexpr double kKeepLeaderShare = 0.4;  // and after 12
constexpr double kFarBehind = 0.25;

// A candidate's figures, for the log and the report.
struct CandidateFigures {
  Term term = Term::None;
  int iterations = 0;    // accepted iterations it ran
  double g_abd = 0;      // its best G_ABD
  double mean_disp = 0;  // of its best iterate
  double max_disp = 0;   // of its best iterate
  bool kept = false;
  bool dropped = false;          // stopped by the trial, not by its own stop rule
  NotRun not_run = NotRun::No;   // why it never started, if it did not
  double weight_factor = 1;      // of the defect weight (auto's stronger rows: group_run.h)
  bool moved_further = false;    // the stronger rows: dropped having moved further than the bound
  bool fell_short = false;       // the stronger rows: dropped short of the bar by their pace, or
                                 // after the rows' plateau by their own first plateau
  Term bounded_by = Term::None;  // the stronger rows after a pick of the rows: whose move bounds
                                 // them (group_run.h); None: the pick's, or none (after_plateau)
  bool after_plateau = false;    // the stronger rows after the rows' plateau: the tolerance alone
                                 // bounds them (group_run.h)
  bool late = false;             // started once the leader had stopped (both, term_race.h)
  double outdone_by = 0;         // the stronger rows: the weight factor of rows that left less
                                 // where these passed their bar, or outpaced these (0: neither)
  bool outpaced = false;         // the stronger rows: stopped where their pace would not beat the
                                 // rows kept so far
};

// The best G_ABD at max_iter if it falls on at its pace over the last `window` (≥ 1) accepted
// iterations (a run with fewer: where it is); a run that has stopped ends where it is.
double projected_g_abd(const Deformation& run, int max_iter, int window = kPlateauIterations);

// A run's figures as a candidate (kept, dropped and started left to the caller).
CandidateFigures candidate_figures(Term term, const Deformation& run);

struct RaceOutcome {
  Term winner = Term::None;
  DeformOutcome outcome;  // the winner's run
  std::vector<CandidateFigures> candidates;
  double initial_g = 0;  // G_ABD at the start
};

// terms: the candidates, in order of preference on a tie; start(term): a fresh run with that
// term; meaningful: the share of the start's G_ABD (δ_ABD / 100) below which a lead is final;
// idle: where the candidates of a round borrow idle threads to step at once (each step depends
// on its own run only, so the outcome does not depend on them);
// progress receives the fraction of max_iter the leader has done.
RaceOutcome race_terms(const std::vector<Term>& terms,
                       const std::function<Deformation(Term)>& start, int max_iter,
                       double meaningful, common::IdleThreads& idle,
                       const std::function<void(double)>& progress);

}  // namespace qd::approximate
