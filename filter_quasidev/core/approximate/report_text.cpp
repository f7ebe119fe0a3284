#include "approximate/report_text.h"

#include "approximate/deformer.h"
#include "approximate/patch_fit.h"
#include "common/format_text.h"

namespace qd::approximate {

using common::format_text;

const char* term_name(Term t) {
  switch (t) {
    case Term::None:
      return "none";
    case Term::Curve:
      return "curve";
    case Term::Defect:
      return "defect";
    case Term::Both:
      return "both";
  }
  return "";
}

const char* join_reason_name(JoinReason r) {
  return r == JoinReason::MostlySeams ? "mostly seams" : "curvature on seams";
}

const char* target_kind_name(TargetKind k) {
  switch (k) {
    case TargetKind::Curve:
      return "curve";
    case TargetKind::ClosedCurve:
      return "closed curve";
    case TargetKind::Plane:
      return "plane";
    case TargetKind::Unchanged:
      return "unchanged";
  }
  return "";
}

const char* pass_name(SolvePass pass) {
  switch (pass) {
    case SolvePass::Only:
      return "";
    case SolvePass::AllAtOnce:
      return "all patches at once";
    case SolvePass::SeamsHeld:
      return "seams held";
    case SolvePass::SeamsFree:
      return "seams free";
  }
  return "";
}

namespace {

// How a candidate ended, for candidates_text: " (kept)", " (left after the trial)" or nothing,
// after when it started if it started late (term_race.h); for auto's stronger rows (group_run.h)
// why they were kept, stopped or not kept (or outdone by another weight), against the pick, against
// the candidate whose move bounds them after a pick of the rows, or after the rows' plateau.
std::string outcome_text(const CandidateReport& c) {
  if (c.weight_factor == 1) {
    std::string what = c.kept ? "kept" : c.dropped ? "left after the trial" : "";
    if (c.late) what = "started when the leader stopped" + (what.empty() ? "" : "; " + what);
    return what.empty() ? "" : " (" + what + ")";
  }
  if (c.outpaced && !c.kept)
    return format_text(" (stopped: its pace would not beat defect ×%g weight)", c.outdone_by);
  if (c.outdone_by > 0)
    return format_text(" (passed, but defect ×%g weight left less)", c.outdone_by);
  if (c.after_plateau) {  // bounded by the tolerance, and no pace stops them
    if (c.kept) return " (kept: half the pick's G_ABD left or less, after its plateau)";
    if (!c.dropped) return " (not kept: left more than half the pick's G_ABD)";
    if (c.moved_further) return " (stopped: moved further than the tolerance)";
    return c.fell_short ? " (stopped: more than half the pick's G_ABD left at their plateau)"
                        : " (stopped: removed nothing)";
  }
  if (c.bounded_by == Term::None) {
    if (c.kept) return " (kept: less G_ABD left, moved less)";
    if (!c.dropped) return " (not kept: left more G_ABD than the pick)";
    return c.moved_further ? " (stopped: moved further than the pick)"
                           : " (stopped: removed nothing)";
  }
  const std::string bound = term_name(c.bounded_by);
  if (c.kept) return " (kept: half the pick's G_ABD left or less, moved less than " + bound + ")";
  if (!c.dropped) return " (not kept: left more than half the pick's G_ABD)";
  if (c.moved_further) return " (stopped: moved further than " + bound + ")";
  return c.fell_short ? " (stopped: its pace would not halve the pick's G_ABD)"
                      : " (stopped: removed nothing)";
}

// " curve −0.0% in 1 it. (left after the trial), defect …" for a patch's candidates.
std::string candidates_text(const PatchReport& p) {
  std::string s;
  std::string not_run;  // the candidates that never started (term_race.h), and why
  NotRun why = NotRun::No;
  for (const CandidateReport& c : p.candidates) {
    if (!c.started()) {
      not_run += std::string(not_run.empty() ? " " : " and ") + term_name(c.term);
      why = c.not_run;
      continue;
    }
    s += std::string(" ") + term_name(c.term) +
         (c.weight_factor != 1 ? format_text(" ×%g weight", c.weight_factor) : std::string()) +
         format_text(" −%.1f%% in %d it.", c.abd_reduction, c.iterations) + outcome_text(c) + ",";
  }
  if (!s.empty()) s.pop_back();
  if (why != NotRun::No)
    s += ";" + not_run + " not run: " +
         (why == NotRun::TargetsRemovedNothing
              ? std::string("the first step of curve removed nothing, that of defect some")
              : std::string(why == NotRun::LeftLittle ? "the first step" : "the first two steps") +
                    " of " + term_name(p.candidates.front().term) +
                    " left less than δ_ABD of G_ABD");
  return s;
}

}  // namespace

std::string term_choice_text(const PatchReport& p) {
  switch (p.developability_reason) {
    case TermChoice::AsAsked:
      return "as asked";
    case TermChoice::Planar:
      return "planar";
    case TermChoice::TooSmall:
      return "too small";
    case TermChoice::NoCurveFits:
      return "no Gauss-image curve fits";
    case TermChoice::EarlierPass:
      return "auto: chosen in the earlier pass";
    case TermChoice::AutoNoCurveFits:
      return "auto: no Gauss-image curve fits";
    case TermChoice::AutoNotRaced:
      return format_text(
          "auto: above %td vertices the angle-defect rows are not raced (their "
          "factorisation would cost many times the curve term's run); "
          "developability defect or both runs them",
          kMaxDefectRaceVertices);
    case TermChoice::Auto:
      return "auto";
    case TermChoice::AutoAfterCurve:
      return format_text(
                 "auto: above %td vertices the curve term runs alone, and it removed less than "
                 "δ_ABD of G_ABD, so the angle-defect rows ran too:",
                 kMaxDefectRaceVertices) +
             candidates_text(p);
    case TermChoice::AutoMeasured:
      break;
  }
  return "auto, measured:" + candidates_text(p);
}

std::string pass_stop_text(const PassStop& s) {
  std::string t;
  switch (s.reason) {
    case PatchStop::MaxIter:
      t = "maxIter reached";
      break;
    case PatchStop::Plateau:
      t = format_text("plateau: the last %d iterations removed %.2f%% of G_ABD (< δ_ABD %g%%)",
                      kPlateauIterations, s.plateau_removed, s.stop_abd);
      break;
    case PatchStop::RatioAbd:
      t = "ratio_ABD below δ_ABD";
      break;
    case PatchStop::RatioObd:
      t = "ratio_OBD below δ_OBD";
      break;
    case PatchStop::MoveBound:
      t = "move bound: the next iterate moved further than the move that bounds these rows";
      break;
    case PatchStop::NoStep:
      t = "never-worse rule: iteration " + std::to_string(s.iterations_run + 1) + " refused (" +
          s.detail + ")";
      break;
    case PatchStop::Planar:
      return "planar: the Gauss image is a point, nothing to do";
    case PatchStop::Unfitted:
      return "left unchanged: " + s.detail;
  }
  if (s.refit_after >= 0)
    t += "; the curve was fitted again after iteration " + std::to_string(s.refit_after) +
         (s.refit_behind ? ", where its re-projected targets had fallen far behind another term's"
                         : ", where its re-projected targets had stalled");
  if (s.anchors_moved_after >= 0)
    t += "; the anchors moved to the positions of iteration " +
         std::to_string(s.anchors_moved_after) + ", where the angle-defect rows had stalled";
  if (s.kept < s.iterations_run)
    t += "; iteration " + std::to_string(s.kept) + " of " + std::to_string(s.iterations_run) +
         " had the least curvature and is kept";
  return t;
}

std::string stop_reason_text(const std::vector<PassStop>& stops) {
  std::string out;
  for (const PassStop& s : stops) {
    if (!out.empty()) out += "; then ";
    if (s.pass != SolvePass::Only) out += pass_name(s.pass) + std::string(": ");
    out += pass_stop_text(s);
  }
  return out;
}

}  // namespace qd::approximate
