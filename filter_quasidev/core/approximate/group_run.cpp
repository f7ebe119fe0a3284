#include "approximate/group_run.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <optional>

#include "approximate/common_names.h"
#include "common/stage_timer.h"

namespace qd::approximate {
namespace {

// With a total tolerance, what each vertex has left of its budget after the moves of earlier
// groups (input: the positions before any): |v' − v_now| ≤ δ − |v_now − v_input| keeps
// |v' − v_input| ≤ δ.
void spend_earlier_moves(GroupMesh& g, const Positions& input) {
  for (size_t l = 0; l < g.global_vertex.size(); ++l) {
    const double moved =
        (g.V0.row(static_cast<Eigen::Index>(l)) - input.row(g.global_vertex[l])).norm();
    g.tolerance[l] = std::max(0.0, g.tolerance[l] - moved);
  }
}

// The fits with `term` on every patch the race decides (a patch no curve fits takes the
// defect rows instead of the curve targets).
std::vector<PatchFit> with_term(std::vector<PatchFit> fits, Term term) {
  for (PatchFit& p : fits)
    if (p.reason == TermReason::Measured)
      p.term = p.fitted() || term == Term::Defect ? term : Term::Defect;
  return fits;
}

// Step 1: each patch's fit and term; the candidates of the race when a term is to be measured.
std::vector<Term> choose_terms(GroupRun& run, const Params& params, const DecidedTerms& decided,
                               size_t threads) {
  const GroupMesh& g = run.group;
  std::vector<Term> candidates;
  run.fits = fit_patches(g, g.V0, threads);
  for (PatchFit& p : run.fits) {
    choose_term(p, params.developability);
    const auto given = decided.find(p.id);
    if (p.reason != TermReason::Measured) continue;
    if (given != decided.end()) {
      p.term = given->second;
      p.reason = TermReason::Given;
    } else if (candidates.size() < 2) {
      candidates = candidate_terms(p, g.solve_vertices);
    }
  }
  if (candidates.size() == 1) run.fits = with_term(run.fits, candidates.front());
  run.targets = group_targets(g, run.fits);
  return candidates;
}

// A run of Step 2 on the group with the terms of `fits`, which must outlive it (its re-projection
// keeps a reference to them).
Deformation start_run(const GroupMesh& g, const std::vector<PatchFit>& fits, SystemLayouts& layouts,
                      const Params& params, size_t threads) {
  return Deformation(g, group_targets(g, fits), make_retarget(g, fits, threads),
                     refits_when_stalled(fits, params), layouts, group_defect_rows(g, fits),
                     params);
}

// Step 2 as a race of the candidate terms; the run keeps the winner's fits and outcome.
// layouts: the group's, which the candidates share (the order and the analyses);
// threads: the group's share, for each candidate's own work; idle: the round's idle threads,
// which step candidates at once.
void race(GroupRun& run, const std::vector<Term>& candidates, const Params& params,
          SystemLayouts& layouts, size_t threads, common::IdleThreads& idle,
          const std::function<void(double)>& progress) {
  const GroupMesh& g = run.group;
  // Each candidate's fits outlive its run: the re-projection keeps a reference to them.
  std::map<Term, std::vector<PatchFit>> fits_of;
  for (Term t : candidates) fits_of[t] = with_term(run.fits, t);
  const auto start = [&](Term t) { return start_run(g, fits_of.at(t), layouts, params, threads); };
  RaceOutcome raced =
      race_terms(candidates, start, params.max_iter, params.stop_abd / 100, idle, progress);
  run.fits = fits_of.at(raced.winner);
  run.targets = group_targets(g, run.fits);
  run.outcome = std::move(raced.outcome);
  run.race = std::move(raced.candidates);
  run.initial_g = raced.initial_g;
}

// Auto on a group above kMaxDefectRaceVertices: the curve term alone, whose conjugate gradients
// cost a fraction of the angle-defect rows' factorisations (patch_fit.h). Where it removes less
// than δ_ABD of the start's G_ABD (what the race calls no lead, term_race.h), that saving bought
// nothing: the angle-defect rows run from the same start too, and the group keeps the one that
// leaves less G_ABD, both reported as candidates (the tangent developable with bumps of 0.5 AE
// and jitter of 0.1 AE at 77k faces, every curve step folding faces: −0.0 % → −98.5 %).
void curve_then_defect(GroupRun& run, const Params& params, double ae, size_t threads,
                       const std::function<void(double)>& progress) {
  const GroupMesh& g = run.group;
  double reported = 0;  // the progress, never back
  const auto run_term = [&](const std::vector<PatchFit>& fits, Term term, CandidateFigures& c) {
    SystemLayouts layouts(g, params, ae);  // not shared: the curve term's go before the next run
    Deformation d = start_run(g, fits, layouts, params, threads);
    while (d.step())
      if (progress)
        progress(reported =
                     std::max(reported, static_cast<double>(d.iterations()) / params.max_iter));
    run.initial_g = d.initial_g_abd();  // the same for both: they start from the same positions
    c = candidate_figures(term, d);
    return d.finish();  // its system and factors go with it
  };
  CandidateFigures curve, defect;
  run.outcome = run_term(run.fits, Term::Curve, curve);
  if (run.initial_g - curve.g_abd >= params.stop_abd / 100 * run.initial_g) return;
  std::vector<PatchFit> defect_fits = with_term(run.fits, Term::Defect);
  DeformOutcome other = run_term(defect_fits, Term::Defect, defect);
  const bool keep_defect = defect.g_abd < curve.g_abd;
  if (keep_defect) {
    std::swap(run.outcome, other);
    run.fits = std::move(defect_fits);
    for (PatchFit& p : run.fits) p.after_curve = p.reason == TermReason::Measured;
    run.targets = group_targets(g, run.fits);
  }
  run.outcome.times += other.times;
  (keep_defect ? defect : curve).kept = true;
  run.race = {curve, defect};
}

// Whether an iterate has moved further than `bound`, on average or at most, by more than
// kMoveRounding of it: two moves both scaled to the tolerance (the stronger rows' first step and
// the bounding candidate's best iterate) are equal but for their last digits, and those digits,
// which depend on how the input was read, must not decide whether the rows run on.
bool moved_further(const Figures& iterate, const Figures& bound) {
  return iterate.mean_disp > bound.mean_disp * (1 + kMoveRounding) ||
         iterate.max_disp > bound.max_disp * (1 + kMoveRounding);
}

// Whose move bounds the stronger rows (group_run.h): the pick's after curve targets (they must
// also leave less than it); after a pick of the rows, a raced candidate's, or the tolerance's
// where the rows stopped at their plateau.
enum class StrongerBound { Pick, Candidate, Tolerance };

// What the stronger rows must do to be kept: leave at most `most_left` of G_ABD and move no
// further than `bound`; bounded_by: the candidate whose move is the bound
// (StrongerBound::Candidate).
struct StrongerBar {
  Figures bound;
  double most_left = 0;
  StrongerBound kind = StrongerBound::Pick;
  Term bounded_by = Term::None;
};

// The bar for the stronger rows after `pick` (the best iterate of the race's winner), if they are
// tried: after curve targets, the pick's; after the rows, where they stopped at their plateau
// before maxIter, no vertex further from the start than the group's tolerance lets any vertex
// move in one iteration; else the move of the raced candidate with curve targets that moved most,
// where that is further than the pick's.
std::optional<StrongerBar> stronger_bar(const GroupRun& run, const Figures& pick) {
  const bool targets = std::any_of(run.fits.begin(), run.fits.end(), [](const PatchFit& p) {
    return p.reason == TermReason::Measured && (p.term == Term::Curve || p.term == Term::Both);
  });
  if (targets) return StrongerBar{pick, pick.g_abd, StrongerBound::Pick, Term::None};
  const double most_left = kStrongerRowsLeave * pick.g_abd;
  if (run.outcome.stop != PatchStop::MaxIter) {
    const std::vector<double>& tolerance = run.group.tolerance;
    Figures bound = pick;
    bound.mean_disp = std::numeric_limits<double>::infinity();
    bound.max_disp = *std::max_element(tolerance.begin(), tolerance.end());
    return StrongerBar{bound, most_left, StrongerBound::Tolerance, Term::None};
  }
  const CandidateFigures* furthest = nullptr;
  for (const CandidateFigures& c : run.race)
    if ((c.term == Term::Curve || c.term == Term::Both) && c.not_run == NotRun::No &&
        (!furthest || c.mean_disp > furthest->mean_disp))
      furthest = &c;
  if (!furthest || !(furthest->mean_disp > pick.mean_disp)) return std::nullopt;
  Figures bound = pick;
  bound.mean_disp = furthest->mean_disp;
  bound.max_disp = furthest->max_disp;
  return StrongerBar{bound, most_left, StrongerBound::Candidate, furthest->term};
}

// What a rung of auto's stronger rows gives.
struct StrongerRun {
  CandidateFigures figures;
  DeformOutcome outcome;
  bool passes = false;
};

// One rung of auto's stronger rows (kStrongerRowsFactors): the rows at `factor` times the
// defect weight from the start, judged against the bar. The rungs step in turn, each reading only
// its own run, so their steps of one round go at once on idle threads.
class StrongerRung {
 public:
  // layouts: the race's, whose order and analyses the rows share (their system scales the rows'
  // weights, deformation_system.h); fits: the group's with the rows, outliving the run.
  StrongerRung(const GroupRun& run, const StrongerBar& bar, double factor,
               const std::vector<PatchFit>& fits, const Params& params, SystemLayouts& layouts,
               size_t threads)
      : bar_(bar),
        factor_(factor),
        max_iter_(params.max_iter),
        d_(start_run(run.group, fits, layouts, with_factor(params, factor), threads)) {
    // They stop at their first iterate beyond the bound, and are judged by their best one
    // within it: dominating the pick, it is kept though a later one moved further.
    d_.keep_best_within([bound = bar.bound](const Figures& f) { return !moved_further(f, bound); });
  }

  // One iteration of a rung still going; it stops by its own stop rule or by the tests below.
  void step() {
    going_ = d_.step() && !moved_further(d_.current(), bar_.bound) && !removed_nothing();
    if (!going_) return;
    short_pace_ = falls_short() || stalled_short();
    going_ = !short_pace_;
  }
  bool going() const { return going_; }
  int iterations() const { return d_.iterations(); }
  double factor() const { return factor_; }
  double best_g_abd() const { return d_.best_g_abd(); }
  // Whether its best iterate so far passes the bar.
  bool passes() const {
    return bar_.kind != StrongerBound::Pick ? d_.best_g_abd() <= bar_.most_left
                                            : d_.best_g_abd() < bar_.most_left;
  }
  // Stops it where its pace would not take it below `to_beat` by maxIter (the G_ABD of a rung
  // that stopped passing, whose weight factor is `by`).
  void stop_if_outpaced(double to_beat, double by) {
    if (going_ && projected() > to_beat) going_ = false, outpaced_by_ = by;
  }

  // Its figures and outcome (call once, after the last step).
  StrongerRun finish() {
    StrongerRun r;
    r.passes = passes();  // (its best iterate is within the bound: keep_best_within above)
    r.figures = candidate_figures(Term::Defect, d_);
    r.figures.weight_factor = factor_;
    // Stopped here, not by its own rule: moved further, removed nothing, fell short or outpaced.
    r.figures.dropped = d_.running();
    r.figures.moved_further = r.figures.dropped && moved_further(d_.current(), bar_.bound);
    r.figures.fell_short = short_pace_;
    r.figures.outpaced = outpaced_by_ > 0;
    r.figures.outdone_by = outpaced_by_;
    r.figures.bounded_by = bar_.bounded_by;
    r.figures.after_plateau = bar_.kind == StrongerBound::Tolerance;
    r.outcome = d_.finish();
    if (r.passes && r.figures.moved_further) r.outcome.stop = PatchStop::MoveBound;
    return r;
  }

 private:
  static Params with_factor(Params params, double factor) {
    params.defect_weight *= factor;
    return params;
  }
  // As in the race (term_race.h), rows that removed nothing in kNothingRounds iterations stop.
  bool removed_nothing() const {
    return d_.iterations() >= kNothingRounds && d_.best_g_abd() >= d_.initial_g_abd();
  }
  // Bounded by a candidate's move, rows stop whose pace over their accepted iterations so far (up
  // to kPlateauIterations) would not take them to the bar by maxIter (projected_g_abd,
  // term_race.h): these rows take their largest steps first, so the pace of their first ones is
  // the most they can hope for (on the garments at --max-iter 5, where none passes, they stop 54
  // of their 131 iterations sooner; on the sweeps none they kept stops). After the rows' plateau
  // the pace does not judge them: they start slowly and gather pace (the irregular tangent with
  // bumps of 0.5 AE, 0.16 wide, 12k faces: 28 % after six iterations, 99 % after thirty), and
  // the pick has spent fewer iterations than maxIter.
  bool falls_short() const {
    return bar_.kind == StrongerBound::Candidate && projected() > bar_.most_left;
  }
  // Where their pace over their accepted iterations so far (up to kPlateauIterations) would take
  // them by maxIter; none before the first.
  double projected() const {
    const int accepted = static_cast<int>(d_.best_track().size()) - 1;
    return accepted >= 1 ? projected_g_abd(d_, max_iter_, std::min(accepted, kPlateauIterations))
                         : -std::numeric_limits<double>::infinity();
  }
  // After the rows' plateau their own first plateau judges them instead: where it finds them
  // above the bar, they stop there rather than move their anchors for a second phase (on the
  // sweeps none reached the bar in one; on the garments the second phases were half their cost).
  bool stalled_short() const {
    return bar_.kind == StrongerBound::Tolerance && d_.anchors_moved() &&
           d_.best_g_abd() > bar_.most_left;
  }

  const StrongerBar& bar_;
  double factor_;
  int max_iter_;
  Deformation d_;
  bool going_ = true;
  bool short_pace_ = false;  // its last step fell short of the bar (falls_short, stalled_short)
  double outpaced_by_ = 0;   // the weight factor of the rung that outpaced it (0: none)
};

// Auto's stronger angle-defect rows after its pick: every rung of kStrongerRowsFactors runs from
// the start against the same bar, one iteration each in turn, the steps of a round at once on
// idle threads, and the group keeps the rung that passes it and leaves least G_ABD (on a tie the
// stronger pull), else the pick. At the end of each round, a rung stops once its pace would not
// take it below a stronger rung that has stopped and passes (the one that leaves least of
// those). Each step reads only its own rung and the rule the round's end, so neither the outcome
// nor the figures depend on the threads. Run one after the other (stop 62), a weaker rung was
// judged from its first iteration on by a stronger one kept before it started; now it is judged
// only once that one has stopped, so it mostly runs further: over the four sweeps of
// docs/robustness.md 27 members leave less G_ABD and none more, for 5–16 % more factorisations and
// 1–5 % less engine time on two threads ("The rungs at once" there).
void try_stronger_rows(GroupRun& run, const Params& params, SystemLayouts& layouts, size_t threads,
                       common::IdleThreads& idle, const std::function<void(double)>& progress) {
  if (run.outcome.history.empty()) return;                  // (an unmoved pick: nothing moves less)
  const Figures pick = run.outcome.history.back().figures;  // its best iterate's
  // Less than δ_ABD of the start's G_ABD left: nothing could remove a meaningful share more.
  if (pick.g_abd <= params.stop_abd / 100 * run.initial_g) return;
  const std::optional<StrongerBar> bar = stronger_bar(run, pick);
  if (!bar) return;
  std::vector<PatchFit> fits = with_term(run.fits, Term::Defect);  // outlives the rungs' steps
  std::vector<StrongerRung> rungs;
  rungs.reserve(std::size(kStrongerRowsFactors));
  for (const double factor : kStrongerRowsFactors)
    rungs.emplace_back(run, *bar, factor, fits, params, layouts, threads);
  for (;;) {
    std::vector<size_t> stepping;
    for (size_t k = 0; k < rungs.size(); ++k)
      if (rungs[k].going()) stepping.push_back(k);
    if (stepping.empty()) break;
    common::run_with_idle_threads(idle, stepping.size(),
                                  [&](size_t i) { rungs[stepping[i]].step(); });
    double to_beat = std::numeric_limits<double>::infinity(), by = 0;
    for (StrongerRung& r : rungs) {  // the stronger pull first
      r.stop_if_outpaced(to_beat, by);
      if (!r.going() && r.passes() && r.best_g_abd() < to_beat)
        to_beat = r.best_g_abd(), by = r.factor();
    }
    int most = 0;
    for (const StrongerRung& r : rungs) most = std::max(most, r.iterations());
    progress(static_cast<double>(most) / params.max_iter);
  }
  std::optional<StrongerRun> kept;
  size_t kept_index = 0;              // of its figures in run.race
  StageTimes spent;                   // by every rung but the kept one
  for (StrongerRung& rung : rungs) {  // the stronger pull first
    StrongerRun r = rung.finish();
    if (!r.passes || (kept && !(r.figures.g_abd < kept->figures.g_abd))) {
      if (r.passes) r.figures.outdone_by = kept->figures.weight_factor;
      spent += r.outcome.times;
      run.race.push_back(r.figures);
      continue;
    }
    if (kept) {
      run.race[kept_index].kept = false;
      run.race[kept_index].outdone_by = r.figures.weight_factor;
      spent += kept->outcome.times;
    }
    r.figures.kept = true;
    kept_index = run.race.size();
    run.race.push_back(r.figures);
    kept = std::move(r);
  }
  if (!kept) {
    run.outcome.times += spent;
    return;
  }
  for (size_t i = 0; i < kept_index; ++i) run.race[i].kept = false;
  kept->outcome.times += run.outcome.times;
  kept->outcome.times += spent;
  run.outcome = std::move(kept->outcome);
  run.fits = std::move(fits);  // (every rung has finished)
  run.targets = group_targets(run.group, run.fits);
}

}  // namespace

GroupRun run_group(const SolveInput& in, const Positions& V, const std::vector<int>& faces,
                   const std::vector<char>& constrained, const Params& params,
                   const DecidedTerms& decided, bool one_unit, common::IdleThreads& idle,
                   const std::function<void(double)>& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  GroupRun run;
  double setup_ms = 0;
  {
    StageTimer timer(setup_ms);
    run.group =
        extract_group(V, in.F, faces, in.patch, constrained, in.interior, in.incident, params);
    for (size_t l = 0; l < run.group.global_vertex.size(); ++l)
      run.group.V_input.row(static_cast<Eigen::Index>(l)) =
          in.input.row(run.group.global_vertex[l]);
    if (one_unit)
      std::fill(run.group.face_unit.begin(), run.group.face_unit.end(),
                run.group.face_patch.front());
    if (params.tolerance_mode == ToleranceMode::Total) spend_earlier_moves(run.group, in.input);
  }
  const GroupMesh& g = run.group;
  const size_t threads = static_cast<size_t>(params.threads);
  double reported = 0;  // the progress, never back: the stronger rows start again from 0
  const auto forward = [&](double fraction) {
    if (progress && fraction > reported) progress(reported = fraction);
  };
  double step1_ms = 0;
  std::vector<Term> candidates;  // of the race, when a patch's term is to be measured
  {
    StageTimer timer(step1_ms);
    candidates = choose_terms(run, params, decided, threads);
  }
  bool all_idle = candidates.size() < 2;
  for (const PatchFit& p : run.fits) all_idle = all_idle && p.idle();
  if (all_idle) {
    run.outcome.V = g.V0;
    run.outcome.stop_detail = run.fits.front().skipped;
    run.outcome.stop = run.outcome.stop_detail.empty() ? PatchStop::Planar : PatchStop::Unfitted;
  } else if (candidates.size() > 1) {
    SystemLayouts layouts(g, params, in.ae);  // the race's and the stronger rows'
    race(run, candidates, params, layouts, threads, idle, forward);
    try_stronger_rows(run, params, layouts, threads, idle, forward);
  } else if (candidates == std::vector<Term>{Term::Curve}) {  // by kMaxDefectRaceVertices
    curve_then_defect(run, params, in.ae, threads, progress);
  } else {
    run.outcome = deform(g, run.targets, make_retarget(g, run.fits, threads),
                         refits_when_stalled(run.fits, params), group_defect_rows(g, run.fits),
                         params, in.ae, progress);
  }
  run.outcome.times.setup += setup_ms;
  run.outcome.times.step1 += step1_ms;
  run.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return run;
}

}  // namespace qd::approximate
