#include "approximate/approximate_log.h"

#include <algorithm>
#include <cmath>

#include "approximate/deformer.h"
#include "approximate/patch_fit.h"
#include "approximate/report_text.h"
#include "approximate/segment_first.h"
#include "approximate/solve_schedule.h"
#include "common/format_text.h"

namespace qd::approximate {

using common::format_text;

namespace {

// Above this fit residual the patch is far from one developable surface: the paper's curve
// targets then warn.
constexpr double kFarResidualDeg = 10.0;

// "G_ABD a → b (−r%), " with the sign of the change: a rise reads "(+r%)".
std::string g_abd_change(const Figures& before, const Figures& after, double reduction) {
  return format_text(
      reduction >= 0 ? "G_ABD %.4g → %.4g (−%.1f%%), " : "G_ABD %.4g → %.4g (+%.1f%%), ",
      before.g_abd, after.g_abd, std::abs(reduction));
}

}  // namespace

std::string patch_log_line(const PatchReport& p, double ae) {
  if (p.developability == Term::None && !p.fitted)
    return "patch " + std::to_string(p.id) + ": " + std::to_string(p.faces) + " faces, " +
           stop_reason_text(p.stops);
  const IterationReport last = p.history.empty() ? IterationReport{} : p.history.back();
  const std::string fit = !p.fitted ? "no curve fit"
                                    : target_kind_name(p.target_kind) +
                                          format_text(" fit residual %.2f°", p.fit_residual_deg);
  std::string s =
      "patch " + std::to_string(p.id) + ": " + std::to_string(p.faces) + " faces, " + fit +
      ", developability " + term_name(p.developability) + " (" + term_choice_text(p) + "), " +
      std::to_string(p.iterations) + " iteration(s) (stop: " + stop_reason_text(p.stops) + "), " +
      g_abd_change(p.before, p.after, p.abd_reduction) +
      format_text("last ratio_ABD %.1f%%, ratio_OBD %.1f%%, ", last.ratio_abd, last.ratio_obd) +
      format_text("max displacement %.3g AE, %.0f ms", p.after.max_disp / ae, p.time_ms);
  if (p.developability == Term::Curve && p.fit_residual_deg > kFarResidualDeg)
    s += format_text(
             "; warning: fit residual %.1f°: this patch is far from one developable surface, "
             "which the paper's method assumes: ",
             p.fit_residual_deg) +
         "use the angle-defect term (developability defect" +
         // auto took the curve term here without measuring the others, so it is no remedy
         (p.developability_reason == TermChoice::AutoNotRaced
              ? "; auto does not race it on a group this large"
              : " or auto") +
         "), or split it into finer patches";
  return s;
}

namespace {

std::string total_log_line(const Result& r) {
  int iterations = 0;
  for (const PatchReport& p : r.patches) iterations = std::max(iterations, p.iterations);
  return "total: " + std::to_string(r.patches.size()) + " patch(es), " +
         g_abd_change(r.total_before, r.total_after, r.abd_reduction) +
         format_text("max displacement %.3g AE (AE = %.4g), ",
                     r.total_after.max_disp / r.average_edge, r.average_edge) +
         "up to " + std::to_string(iterations) + " iterations, " +
         format_text("%d factorisation(s), %.0f ms", r.factorizations, r.time_ms);
}

// When the run removed less than half of the curvature: why, with the figures the engine has,
// and what to try.
std::vector<std::string> advice(const Result& r, const Params& params, double held_share) {
  std::vector<std::string> out;
  if (r.abd_reduction >= 50.0) return out;
  const std::string head = format_text("little was removed (%.1f%% of G_ABD): ", r.abd_reduction);
  if (held_share >= 25.0)
    out.push_back(
        head +
        format_text("%.0f%% of the curvature lies on vertices that do not move (", held_share) +
        (params.seams == SeamMode::Fixed ? "fixed seams, " : "") +
        (params.keep_boundary ? "the kept boundary, " : "") +
        "the selection); free seams or a free boundary can reach it");
  for (const PatchReport& p : r.patches) {
    const bool capped = std::any_of(p.stops.begin(), p.stops.end(), [](const PassStop& s) {
      return s.reason == PatchStop::MaxIter;
    });
    if (capped && p.history.size() > static_cast<size_t>(kPlateauIterations)) {
      const double then = p.history[p.history.size() - 1 - kPlateauIterations].figures.g_abd;
      const double removed =
          then > 0 ? 100.0 * (then - p.history.back().figures.g_abd) / then : 0.0;
      out.push_back(
          head + "patch " + std::to_string(p.id) +
          format_text(" stopped at maxIter while its last %d iterations still removed %.1f%% "
                      "of its curvature: a larger maxIter goes further",
                      kPlateauIterations, removed));
    }
  }
  if (out.empty())
    out.push_back(head +
                  "the patches stopped where no step of their terms removes more within the "
                  "tolerance (their lines give the candidates' figures); a larger tolerance or "
                  "developability weight moves the surface further for more");
  return out;
}

}  // namespace

std::vector<std::string> approximate_log(const Result& r,
                                         const std::vector<std::vector<int>>& reruns,
                                         const Params& params, double held_share) {
  std::vector<std::string> log;
  for (const std::string& w : r.warnings) log.push_back("warning: " + w);
  if (skips_all_at_once(params, r.V.rows()))
    log.push_back(format_text(
        "note: above %ld vertices auto races no term on all patches at once, so that pass is "
        "skipped: the patches are solved with their seams held, then free, each racing its "
        "own terms (--developability curve, defect or both runs it)",
        static_cast<long>(kMaxDefectRaceVertices)));
  for (const PatchJoin& j : r.joins)
    log.push_back("note: patch " + std::to_string(j.patch) + " (" + std::to_string(j.faces) +
                  (j.faces == 1 ? " face" : " faces") + ") has " +
                  (j.reason == JoinReason::MostlySeams
                       ? "most of its vertices on seams"
                       : "more of its curvature on its seams than inside") +
                  ": it is solved together with patch " + std::to_string(j.group) +
                  ", and the seam between them moves");
  for (const std::vector<int>& ids : reruns) {
    std::string list;
    for (int id : ids) list += (list.empty() ? "" : ", ") + std::to_string(id);
    log.push_back("note: patches " + list +
                  ", solved at once, raised the curvature where they meet; solved again one "
                  "after the other");
  }
  if (r.times.substituted > 0)
    log.push_back("note: " + std::to_string(r.times.substituted) +
                  " system(s) with angle-defect rows are quasi-definite, which LLᵀ cannot "
                  "factorise: they were factorised by LDLᵀ instead (the result is the same)");
  for (const PatchReport& p : r.patches) log.push_back(patch_log_line(p, r.average_edge));
  log.push_back(total_log_line(r));
  for (const std::string& line : advice(r, params, held_share)) log.push_back("note: " + line);
  return log;
}

std::string join_trial_note(const JoinTrial& t) {
  return format_text(
      "note: %d patch(es) have more of their curvature on their seams than inside: solved with "
      "them joined to a neighbour, G_ABD −%.1f%%, and with their seams held, −%.1f%%: kept %s",
      t.patches, t.joined, t.held, t.kept_joined ? "joined" : "held");
}

std::string segmented_note(const std::string& why, int count, const SettingText& setting) {
  return "note: the mesh has no patch ids and " + why + ": split into " + std::to_string(count) +
         " nearly developable patches (segment, largest fit error " +
         std::to_string(static_cast<int>(kSegmentFirstMaxErrorDeg)) +
         "°), solved with free seams (" + setting_text(setting, "segment_first", "never") +
         " keeps it one patch)";
}

}  // namespace qd::approximate
