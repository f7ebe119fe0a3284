#include "approximate/approximate_log.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace qd {
namespace {

// Above this fit residual the patch is far from one developable surface: the paper's curve
// targets then warn.
constexpr double kFarResidualDeg = 10.0;

std::string format(const char* fmt, double a, double b = 0, double c = 0, double d = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b, c, d);
  return buf;
}

// "G_ABD a → b (−r%), " with the sign of the change: a rise reads "(+r%)".
std::string g_abd_change(const Figures& before, const Figures& after, double reduction) {
  return format(reduction >= 0 ? "G_ABD %.4g → %.4g (−%.1f%%), " : "G_ABD %.4g → %.4g (+%.1f%%), ",
                before.g_abd, after.g_abd, std::abs(reduction));
}

}  // namespace

const char* term_name(Term t) {
  return t == Term::Curve ? "curve" : t == Term::Defect ? "defect" : t == Term::Both ? "both" : "none";
}

std::vector<CandidateReport> candidate_reports(const std::vector<CandidateFigures>& race,
                                               double initial_g) {
  std::vector<CandidateReport> out;
  for (const CandidateFigures& c : race)
    out.push_back({term_name(c.term), c.iterations,
                   initial_g > 0 ? 100.0 * (initial_g - c.g_abd) / initial_g : 0.0, c.mean_disp,
                   c.kept, c.dropped});
  return out;
}

std::string term_reason_text(const PatchFit& p, const std::vector<CandidateReport>& candidates) {
  switch (p.reason) {
    case TermReason::AsAsked: return "as asked";
    case TermReason::Planar: return "planar";
    case TermReason::TooSmall: return "too small";
    case TermReason::NoCurveFits: return "no Gauss-image curve fits";
    case TermReason::Given: return "auto: chosen in the earlier pass";
    case TermReason::Measured: break;
  }
  if (!p.fitted()) return "auto: no Gauss-image curve fits";
  if (candidates.empty() && p.term == Term::Curve)
    return format("auto: above %d vertices the angle-defect rows are not raced (their "
                  "factorisation would cost many times the curve term's run); developability "
                  "defect or both runs them",
                  static_cast<int>(kMaxDefectRaceVertices));
  if (candidates.empty()) return "auto";
  std::string s = "auto, measured:";
  for (const CandidateReport& c : candidates)
    s += " " + c.term + format(" −%.1f%% in %.0f it.", c.abd_reduction, c.iterations) +
         (c.kept ? " (kept)" : c.dropped ? " (left after the trial)" : "") + ",";
  s.pop_back();
  return s;
}

std::string stop_text(const DeformOutcome& o, const Params& params) {
  std::string s;
  switch (o.stop) {
    case StopReason::Running:
    case StopReason::MaxIter: s = "maxIter reached"; break;
    case StopReason::Plateau:
      s = format("plateau: the last %.0f iterations removed %.2f%% of G_ABD (< δ_ABD %g%%)",
                 kPlateauIterations, o.plateau_removed, params.stop_abd);
      break;
    case StopReason::RatioAbd: s = "ratio_ABD below δ_ABD"; break;
    case StopReason::RatioObd: s = "ratio_OBD below δ_OBD"; break;
    case StopReason::NothingToDo: return o.stop_detail;
    case StopReason::NoStep:
      s = "never-worse rule: iteration " + std::to_string(o.iterations_run + 1) + " refused (" +
          o.stop_detail + ")";
      break;
  }
  const int kept = static_cast<int>(o.history.size());
  if (kept < o.iterations_run)
    s += "; iteration " + std::to_string(kept) + " of " + std::to_string(o.iterations_run) +
         " had the least curvature and is kept";
  return s;
}

std::string patch_log_line(const PatchReport& p, double ae) {
  if (p.developability == "none" && p.target_kind == "unchanged")
    return "patch " + std::to_string(p.id) + ": " + std::to_string(p.faces) + " faces, " +
           p.stop_reason;
  const IterationReport last = p.history.empty() ? IterationReport{} : p.history.back();
  const std::string fit = p.target_kind == "unchanged"
                              ? "no curve fit"
                              : p.target_kind + format(" fit residual %.2f°", p.fit_residual_deg);
  std::string s = "patch " + std::to_string(p.id) + ": " + std::to_string(p.faces) + " faces, " +
                  fit + ", developability " + p.developability + " (" + p.developability_reason +
                  "), " + std::to_string(p.iterations) + " iteration(s) (stop: " + p.stop_reason +
                  "), " + g_abd_change(p.before, p.after, p.abd_reduction) +
                  format("last ratio_ABD %.1f%%, ratio_OBD %.1f%%, ", last.ratio_abd, last.ratio_obd) +
                  format("max displacement %.3g AE, %.0f ms", p.after.max_disp / ae, p.time_ms);
  if (p.developability == "curve" && p.fit_residual_deg > kFarResidualDeg)
    s += format(
        "; warning: fit residual %.1f°: this patch is far from one developable surface, which "
        "the paper's method assumes: use the angle-defect term (developability defect or auto), "
        "or split it into finer patches",
        p.fit_residual_deg);
  return s;
}

std::string total_log_line(const Result& r) {
  int iterations = 0;
  for (const PatchReport& p : r.patches) iterations = std::max(iterations, p.iterations);
  return "total: " + std::to_string(r.patches.size()) + " patch(es), " +
         g_abd_change(r.total_before, r.total_after, r.abd_reduction) +
         format("max displacement %.3g AE (AE = %.4g), ", r.total_after.max_disp / r.average_edge,
                r.average_edge) +
         "up to " + std::to_string(iterations) + " iterations, " + std::to_string(r.factorizations) +
         format(" factorisation(s), %.0f ms", r.time_ms);
}

std::vector<std::string> advice(const Result& r, const Params& params, double held_share) {
  std::vector<std::string> out;
  if (r.abd_reduction >= 50.0) return out;
  const std::string head = format("little was removed (%.1f%% of G_ABD): ", r.abd_reduction);
  if (held_share >= 25.0)
    out.push_back(head + format("%.0f%% of the curvature lies on vertices that do not move (", held_share) +
                  (params.seams == SeamMode::Fixed ? "fixed seams, " : "") +
                  (params.keep_boundary ? "the kept boundary, " : "") +
                  "the selection); free seams or a free boundary can reach it");
  for (const PatchReport& p : r.patches) {
    const bool capped = p.stop_reason.find("maxIter reached") != std::string::npos;
    if (capped && p.history.size() > static_cast<size_t>(kPlateauIterations)) {
      const double then = p.history[p.history.size() - 1 - kPlateauIterations].figures.g_abd;
      const double removed = then > 0 ? 100.0 * (then - p.history.back().figures.g_abd) / then : 0.0;
      out.push_back(head + "patch " + std::to_string(p.id) +
                    format(" stopped at maxIter while its last %.0f iterations still removed %.1f%% "
                           "of its curvature: a larger maxIter goes further",
                           kPlateauIterations, removed));
    }
  }
  if (out.empty())
    out.push_back(head + "the patches stopped where no step of their terms removes more within the "
                         "tolerance (their lines give the candidates' figures); a larger tolerance or "
                         "developability weight moves the surface further for more");
  return out;
}

}  // namespace qd
