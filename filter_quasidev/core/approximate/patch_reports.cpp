#include "approximate/patch_reports.h"

#include <algorithm>
#include <cassert>

#include "approximate/group_mesh.h"

namespace qd::approximate {
namespace {

std::vector<CandidateReport> candidate_reports(const std::vector<CandidateFigures>& race,
                                               double initial_g) {
  std::vector<CandidateReport> out;
  for (const CandidateFigures& c : race)
    out.push_back({c.term, c.iterations,
                   initial_g > 0 ? 100.0 * (initial_g - c.g_abd) / initial_g : 0.0, c.mean_disp,
                   c.kept, c.dropped, c.not_run, c.weight_factor, c.moved_further, c.late,
                   c.fell_short, c.bounded_by, c.after_plateau, c.outdone_by, c.outpaced});
  return out;
}

TermChoice term_choice(const PatchFit& p, bool raced) {
  switch (p.reason) {
    case TermReason::AsAsked:
      return TermChoice::AsAsked;
    case TermReason::Planar:
      return TermChoice::Planar;
    case TermReason::TooSmall:
      return TermChoice::TooSmall;
    case TermReason::NoCurveFits:
      return TermChoice::NoCurveFits;
    case TermReason::Given:
      return TermChoice::EarlierPass;
    case TermReason::Measured:
      break;
  }
  if (!p.fitted()) return TermChoice::AutoNoCurveFits;
  if (raced) return p.after_curve ? TermChoice::AutoAfterCurve : TermChoice::AutoMeasured;
  return p.term == Term::Curve ? TermChoice::AutoNotRaced : TermChoice::Auto;
}

PassStop pass_stop(const PatchFit& p, const DeformOutcome& o, SolvePass pass,
                   const Params& params) {
  PassStop s;
  s.pass = pass;
  if (p.idle() && !p.fitted()) {
    s.reason = PatchStop::Unfitted;
    s.detail = p.skipped;
    return s;
  }
  s.reason = o.stop;
  s.plateau_removed = o.plateau_removed;
  s.stop_abd = params.stop_abd;
  s.iterations_run = o.iterations_run;
  s.kept = static_cast<int>(o.history.size());
  s.refit_after = o.refit_after;
  s.refit_behind = o.refit_behind;
  s.anchors_moved_after = o.anchors_moved_after;
  s.detail = o.stop_detail;
  return s;
}

}  // namespace

SolveReports patch_reports(const SolveSchedule& s, const Params& params, size_t faces) {
  SolveReports out;
  out.times = s.replaced_times;
  out.initial_target.resize(faces);
  for (const ScheduledRun& scheduled : s.runs) {
    const GroupRun& run = scheduled.run;
    if (!scheduled.reused) out.times += run.outcome.times;  // the work of this solve
    assert(run.targets.size() == static_cast<size_t>(run.group.solve_faces));
    for (size_t f = 0; f < run.targets.size(); ++f)
      out.initial_target[static_cast<size_t>(run.group.global_face[f])] = run.targets[f];
    for (const PatchFit& p : run.fits) {
      PatchReport& rep = out.patches[p.id];
      const bool first = rep.stops.empty();
      rep.id = p.id;
      rep.target_kind = p.fit.model->kind();
      rep.fitted = p.fitted();
      rep.fit_residual_deg = p.fit.residual_deg;
      rep.tolerance = patch_tolerance(params, p.id);
      rep.iterations += static_cast<int>(run.outcome.history.size());
      rep.iterations_run += run.outcome.iterations_run;
      rep.developability = p.term;
      if (!run.race.empty()) rep.candidates = candidate_reports(run.race, run.initial_g);
      if (first || !run.race.empty())
        rep.developability_reason = term_choice(p, !rep.candidates.empty());
      rep.stops.push_back(pass_stop(p, run.outcome, scheduled.pass, params));
      if (first && p.idle() && !p.fitted() && out.unfitted++ == 0) {
        out.first_unfitted = p.id;
        out.first_unfitted_why = p.skipped;
      }
      rep.history.insert(rep.history.end(), run.outcome.history.begin(), run.outcome.history.end());
      rep.time_ms += run.time_ms / static_cast<double>(run.fits.size());
      rep.times += run.outcome.times;
      rep.group_patches = std::max(rep.group_patches, static_cast<int>(run.fits.size()));
    }
  }
  return out;
}

}  // namespace qd::approximate
