#include "approximate_report_json.h"

#include "approximate/report_text.h"
#include "approximate_params.h"
#include "common/serial_libraries.h"
#include "params_json.h"
#include "report_text.h"

namespace qd::frontend {

namespace {

Json figures(const common::Figures& f) {
  return {{"g_abd", f.g_abd},         {"angle_defect", f.angle_defect},
          {"max_abs_k", f.max_abs_k}, {"obd", f.obd},
          {"shape", f.shape},         {"max_disp", f.max_disp},
          {"mean_disp", f.mean_disp}};
}

Json iteration(const approximate::IterationReport& it) {
  return {{"iteration", it.iteration},
          {"figures", figures(it.figures)},
          {"ratio_abd", it.ratio_abd},
          {"ratio_obd", it.ratio_obd},
          {"step_scale", it.step_scale},
          {"weight_scale", it.weight_scale},
          {"note", it.note}};
}

// Milliseconds per stage, summed over patches and threads (time_ms is the wall clock); a
// patch's are those of its solve groups, which group_patches patches may share.
Json stage_times(const approximate::StageTimes& t) {
  return {{"setup", t.setup},
          {"step1", t.step1},
          {"assembly", t.assembly},
          {"factorization", t.factorization},
          {"solve", t.solve},
          {"metrics", t.metrics},
          {"factorizations", t.factorizations},
          {"factorization_flops", t.factorization_flops},
          {"solve_bytes", t.solve_bytes},
          {"solves", t.solves},
          {"cg_iterations", t.cg_iterations},
          {"cg_truncated", t.cg_truncated},
          {"substituted", t.substituted}};
}

Json candidate(const approximate::CandidateReport& c) {
  return {{"term", approximate::term_name(c.term)},
          {"iterations", c.iterations},
          {"abd_reduction", c.abd_reduction},
          {"mean_disp", c.mean_disp},
          {"defect_weight_factor", c.weight_factor},
          {"outdone_by_weight_factor", c.outdone_by > 0 ? Json(c.outdone_by) : Json(nullptr)},
          {"outpaced", c.outpaced},
          {"kept", c.kept},
          {"dropped", c.dropped},
          {"started", c.started()},
          {"started_late", c.late},
          {"bounded_by", c.after_plateau ? Json("tolerance")
                         : c.bounded_by == approximate::Term::None
                             ? Json(nullptr)
                             : Json(approximate::term_name(c.bounded_by))}};
}

Json patch(const approximate::PatchReport& p, double average_edge) {
  Json history = Json::array();
  for (const approximate::IterationReport& it : p.history) history.push_back(iteration(it));
  Json candidates = Json::array();
  for (const approximate::CandidateReport& c : p.candidates) candidates.push_back(candidate(c));
  return {{"id", p.id},
          {"faces", p.faces},
          {"vertices", p.vertices},
          {"free_vertices", p.free_vertices},
          {"tolerance_model", p.tolerance},
          {"tolerance_ae", average_edge > 0 ? p.tolerance / average_edge : 0.0},
          {"target_kind", approximate::target_kind_name(p.target_kind)},
          {"developability", approximate::term_name(p.developability)},
          {"developability_reason", approximate::term_choice_text(p)},
          {"candidates", candidates},
          {"fit_residual_deg", p.fit_residual_deg},
          {"iterations", p.iterations},
          {"iterations_run", p.iterations_run},
          {"stop_reason", approximate::stop_reason_text(p.stops)},
          {"before", figures(p.before)},
          {"after", figures(p.after)},
          {"abd_reduction", p.abd_reduction},
          {"obd_reduction", p.obd_reduction},
          {"time_ms", p.time_ms},
          {"stage_ms", stage_times(p.times)},
          {"group_patches", p.group_patches},
          {"history", history}};
}

// The patches solved in a neighbour's group, and the measured choice of joining them.
Json joins(const approximate::Result& r) {
  Json out = Json::array();
  for (const approximate::PatchJoin& j : r.joins)
    out.push_back({{"patch", j.patch},
                   {"faces", j.faces},
                   {"group", j.group},
                   {"reason", approximate::join_reason_name(j.reason)}});
  return out;
}

Json join_trial(const std::optional<approximate::JoinTrial>& t) {
  if (!t) return nullptr;
  return {{"patches", t->patches},
          {"joined", t->joined},
          {"held", t->held},
          {"kept", t->kept_joined ? "joined" : "held"}};
}

}  // namespace

std::string report_json(const approximate::Result& result, const ReportContext& c) {
  Json patches = Json::array();
  for (const approximate::PatchReport& p : result.patches)
    patches.push_back(patch(p, result.average_edge));
  const Json parameters = params::values_json(params::approximate_params(), c.settings);
  const Json report = {{"input", c.input},
                       {"output", c.output},
                       {"vertices", c.vertices},
                       {"faces", c.faces},
                       {"has_patch_ids", c.has_patch_ids},
                       {"segmented_first", !result.segmented_patch.empty()},
                       {"constrained_vertices", c.constrained_vertices},
                       {"average_edge", result.average_edge},
                       {"parameters", parameters},
                       {"total_before", figures(result.total_before)},
                       {"total_after", figures(result.total_after)},
                       {"abd_reduction", result.abd_reduction},
                       {"factorizations", result.factorizations},
                       {"time_ms", result.time_ms},
                       {"stage_ms", stage_times(result.times)},
                       {"blas_kernels", common::loaded_blas_core()},
                       {"patches", patches},
                       {"joins", joins(result)},
                       {"join_trial", join_trial(result.join_trial)},
                       {"warnings", result.warnings},
                       {"notes", c.notes},
                       {"log", result.log}};
  return report_text(report);
}

}  // namespace qd::frontend
