#include "approximate/term_race.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace qd::approximate {
namespace {

// a leads b: less G_ABD, or as much and less mean displacement.
bool leads(const Deformation& a, const Deformation& b) {
  return a.best_g_abd() < b.best_g_abd() ||
         (a.best_g_abd() == b.best_g_abd() && a.best().mean_disp < b.best().mean_disp);
}

// The leading candidate among those not dropped (the first on a tie).
size_t leader(const std::vector<Deformation>& runs, const std::vector<char>& dropped) {
  size_t best = runs.size();
  for (size_t k = 0; k < runs.size(); ++k)
    if (!dropped[k] && (best == runs.size() || leads(runs[k], runs[best]))) best = k;
  return best;
}

// The trailing candidate among those not dropped (the last on a tie).
size_t trailer(const std::vector<Deformation>& runs, const std::vector<char>& dropped) {
  size_t worst = runs.size();
  for (size_t k = 0; k < runs.size(); ++k)
    if (!dropped[k] && (worst == runs.size() || !leads(runs[k], runs[worst]))) worst = k;
  return worst;
}

// The most iterations any candidate not dropped has run: the race's progress.
int most_iterations(const std::vector<Deformation>& runs, const std::vector<char>& dropped) {
  int most = 0;
  for (size_t k = 0; k < runs.size(); ++k)
    if (!dropped[k]) most = std::max(most, runs[k].iterations());
  return most;
}

}  // namespace

double projected_g_abd(const Deformation& run, int max_iter, int window) {
  const std::vector<double>& best = run.best_track();
  const auto n = static_cast<int>(best.size()) - 1;  // accepted iterations
  if (n < window || !run.running()) return run.best_g_abd();
  const double pace = (best[n - window] - best[n]) / window;
  return best[n] - pace * std::max(0, max_iter - n);
}

CandidateFigures candidate_figures(Term term, const Deformation& run) {
  CandidateFigures c;
  c.term = term;
  c.iterations = run.iterations();
  c.g_abd = run.best_g_abd();
  c.mean_disp = run.best().mean_disp;
  c.max_disp = run.best().max_disp;
  return c;
}

RaceOutcome race_terms(const std::vector<Term>& terms,
                       const std::function<Deformation(Term)>& start, int max_iter,
                       double meaningful, common::IdleThreads& idle,
                       const std::function<void(double)>& progress) {
  assert(!terms.empty());
  // The run has left less than δ_ABD of the start's G_ABD: no term could remove a meaningful
  // share more.
  const auto spent = [&](const Deformation& run) {
    return run.best_g_abd() <= meaningful * run.initial_g_abd();
  };
  // Round 1 begins with the first candidate alone (the curve term, whose step costs least): where
  // it leaves less than δ_ABD of the start's G_ABD, the others never start (the last rule below).
  // Where it removed nothing, the angle-defect rows step next, alone too, and both starts only
  // where they removed nothing either (term_race.h); elsewhere they step at once in the loop.
  std::vector<Deformation> runs;
  runs.push_back(start(terms.front()));
  runs.front().step();
  // Where the share of G_ABD that step left, left once more, is less than δ_ABD, the candidate
  // takes its step of round 2 alone too: at that pace the others would never start.
  const double left = runs.front().best_g_abd() / runs.front().initial_g_abd();
  const bool ahead = !spent(runs.front()) && runs.front().running() && left * left <= meaningful;
  if (ahead) runs.front().step();
  size_t stepped = 1;  // the candidates whose step of round 1 is done
  NotRun never = !spent(runs.front()) ? NotRun::No
                 : ahead              ? NotRun::LeftLittleInTwo
                                      : NotRun::LeftLittle;  // the rest's, if any
  const auto removed = [&](size_t k) { return runs[k].initial_g_abd() - runs[k].best_g_abd(); };
  // Whether term t's step of round 1 is done and removed some: 1, 0, or -1 when not yet done.
  const auto first_step_removed = [&](Term t) {
    const auto end = terms.begin() + static_cast<long>(stepped);
    const auto at = std::find(terms.begin(), end, t);
    return at == end ? -1 : removed(static_cast<size_t>(at - terms.begin())) > 0 ? 1 : 0;
  };
  const bool targets_removed_nothing = first_step_removed(Term::Curve) == 0;
  for (size_t k = 1; k < terms.size() && never == NotRun::No; ++k) {
    if (terms[k] == Term::Both && targets_removed_nothing &&
        first_step_removed(Term::Defect) == 1) {
      never = NotRun::TargetsRemovedNothing;
      break;
    }
    runs.push_back(start(terms[k]));
    if (targets_removed_nothing && k + 1 < terms.size() && terms[k + 1] == Term::Both &&
        stepped == k) {
      runs.back().step();
      stepped = runs.size();
    }
  }
  std::vector<char> dropped(runs.size(), 0);
  const auto active = [&](size_t k) { return runs[k].running() && !dropped[k]; };
  const auto any_active = [&] {
    for (size_t k = 0; k < runs.size(); ++k)
      if (active(k)) return true;
    return false;
  };
  const int drop_worst_after =
      std::max(1, static_cast<int>(std::lround(kDropWorstShare * max_iter)));
  const int drop_nothing_after = std::min(kNothingRounds, drop_worst_after);
  const int keep_leader_after =
      std::max(drop_worst_after + 1, static_cast<int>(std::lround(kKeepLeaderShare * max_iter)));
  bool worst_dropped = false;
  // The curve term, when the rules would drop it after as many rounds as the plateau rule gives
  // its re-projected targets, is re-fitted instead (once, where the budget leaves its new targets
  // kPlateauIterations rounds), and the rules spare it for those rounds.
  std::vector<int> spared_until(runs.size(), 0);
  int round = 1;
  const auto refits = [&](size_t k) {
    return terms[k] == Term::Curve && round >= kPlateauIterations &&
           round + kPlateauIterations < max_iter && runs[k].refit_targets(true);
  };
  // A rejoined candidate with curve targets that its steps since the rejoin would drop is fitted
  // again instead, once, where its own budget leaves the new targets kPlateauIterations
  // iterations: those steps say nothing of the phase its own stop rule would begin at that stall.
  const auto refits_rejoined = [&](size_t k) {
    return terms[k] != Term::Defect && runs[k].iterations() + kPlateauIterations < max_iter &&
           runs[k].refit_targets(true);
  };
  const auto drop = [&](size_t k) {
    if (dropped[k] || round < spared_until[k]) return;
    if (refits(k))
      spared_until[k] = round + 1 + kPlateauIterations;
    else
      dropped[k] = 1;
  };
  // Candidate k may still overtake the leader: it began a new phase (re-fitted targets, moved
  // anchors) fewer than kPlateauIterations iterations ago, so a pace over the phase before says
  // nothing of where this one goes; or, falling on at its pace, it would end below the leader,
  // likewise projected.
  const auto overtakes = [&](size_t k, size_t lead) {
    const int in_phase = runs[k].phase_iterations();
    const bool new_phase =
        runs[k].running() && in_phase < kPlateauIterations && in_phase < runs[k].iterations();
    return new_phase || projected_g_abd(runs[k], max_iter) < projected_g_abd(runs[lead], max_iter);
  };
  // A leader that stopped by its own rule before maxIter with more than δ_ABD of the start's
  // G_ABD left: the candidates the trial dropped while they still ran, and that had removed some,
  // rejoin (once), and run on while the steps they take from there give a pace that would take
  // them below it by maxIter. Both, if it never started for the targets' first step, starts then
  // from the same start, and is judged likewise.
  std::vector<int> rejoin_round(runs.size(), 0);  // of its first step after the rejoin; 0: none
  std::vector<char> late(runs.size(), 0);         // started at the rejoin
  // Once: a rejoin that found none ends the race.
  const auto rejoin = [&] {
    if (std::any_of(rejoin_round.begin(), rejoin_round.end(), [](int r) { return r > 0; }))
      return false;
    const size_t lead = leader(runs, dropped);
    if (runs[lead].stop_reason() == PatchStop::MaxIter || spent(runs[lead])) return false;
    bool any = false;
    for (size_t k = 0; k < runs.size(); ++k)
      if (dropped[k] && runs[k].running() && removed(k) > 0)
        dropped[k] = 0, rejoin_round[k] = round, any = true;
    // Both, not started for the targets' first step, starts now from the same start.
    if (never == NotRun::TargetsRemovedNothing) {
      never = NotRun::No;
      for (size_t k = runs.size(); k < terms.size(); ++k, any = true) {
        runs.push_back(start(terms[k]));
        dropped.push_back(0), spared_until.push_back(0);
        rejoin_round.push_back(round), late.push_back(1);
      }
    }
    return any;
  };
  for (; any_active() || rejoin(); ++round) {
    std::vector<size_t> stepping;  // each candidate's step reads only its own run's state
    const size_t first = round == 1 ? stepped : 0;  // round 1's first candidates have stepped
    for (size_t k = first; k < runs.size(); ++k)
      if (active(k) && !(ahead && k == 0 && round == 2)) stepping.push_back(k);
    common::run_with_idle_threads(idle, stepping.size(),
                                  [&](size_t i) { runs[stepping[i]].step(); });
    if (progress) progress(static_cast<double>(most_iterations(runs, dropped)) / max_iter);
    // The rules of term_race.h.
    const size_t lead = leader(runs, dropped);
    const bool lead_runs = runs[lead].running();
    const double meaningful_g = meaningful * runs[lead].initial_g_abd();
    const bool trial = round < drop_worst_after;  // only what removed nothing is behind yet
    const auto behind = [&](size_t k) {
      return trial ? !(removed(k) > 0) : !(removed(k) >= kFarBehind * removed(lead));
    };
    if (lead_runs && round >= drop_nothing_after && removed(lead) > (trial ? meaningful_g : 0))
      for (size_t k = 0; k < runs.size(); ++k)
        if (k != lead && behind(k)) drop(k);
    if (lead_runs && round >= drop_worst_after && !worst_dropped) {
      worst_dropped = true;
      // A trailer whose last full step was refused is ranked by steps it was not allowed to take.
      const size_t worst = trailer(runs, dropped);
      if (std::count(dropped.begin(), dropped.end(), 0) > 2 &&
          !runs[worst].last_full_step_refused())
        drop(worst);
    }
    if (spent(runs[lead])) {
      for (size_t k = 0; k < runs.size(); ++k) dropped[k] = k != lead;
    } else if (lead_runs && round >= keep_leader_after) {
      for (size_t k = 0; k < runs.size(); ++k)
        if (k != lead && !(active(k) && overtakes(k, lead))) drop(k);
    } else if (!lead_runs) {  // a rejoined candidate is judged by its steps since the rejoin
      for (size_t k = 0; k < runs.size(); ++k) {
        const int steps = round - rejoin_round[k] + 1;
        if (rejoin_round[k] > 0 && active(k) &&
            ((steps >= kNothingRounds && !(removed(k) > 0)) ||
             (steps >= kPlateauIterations && !overtakes(k, lead))) &&
            !refits_rejoined(k))
          dropped[k] = 1;
      }
    }
  }
  RaceOutcome out;
  const size_t lead = leader(runs, dropped);
  assert(lead < runs.size());  // the race never drops every candidate
  for (size_t k = 0; k < terms.size(); ++k) {
    CandidateFigures c;
    if (k < runs.size()) {
      c = candidate_figures(terms[k], runs[k]);
      c.kept = k == lead;
      c.dropped = dropped[k] != 0;  // by the race, whether or not it had stopped
      c.late = late[k] != 0;
    } else {
      c.term = terms[k];
      c.g_abd = runs[lead].initial_g_abd();
      c.not_run = never;
      c.dropped = true;
    }
    out.candidates.push_back(c);
  }
  out.winner = terms[lead];
  out.initial_g = runs[lead].initial_g_abd();
  out.outcome = runs[lead].finish();
  for (size_t k = 0; k < runs.size(); ++k)
    if (k != lead) out.outcome.times += runs[k].finish().times;
  return out;
}

}  // namespace qd::approximate
