#include "report_json.h"

#include "json_writer.h"

namespace qd::cli {

namespace {

void write_figures(JsonWriter& j, const char* key, const Figures& f) {
  j.begin_object(key);
  j.value("g_abd", f.g_abd);
  j.value("angle_defect", f.angle_defect);
  j.value("max_abs_k", f.max_abs_k);
  j.value("obd", f.obd);
  j.value("shape", f.shape);
  j.value("max_disp", f.max_disp);
  j.value("mean_disp", f.mean_disp);
  j.end_object();
}

void write_iteration(JsonWriter& j, const IterationReport& it) {
  j.begin_object();
  j.value("iteration", it.iteration);
  write_figures(j, "figures", it.figures);
  j.value("ratio_abd", it.ratio_abd);
  j.value("ratio_obd", it.ratio_obd);
  j.value("step_scale", it.step_scale);
  j.value("note", it.note);
  j.end_object();
}

// Milliseconds per stage, summed over patches and threads (time_ms is the wall clock).
void write_times(JsonWriter& j, const StageTimes& t) {
  j.begin_object("stage_ms");
  j.value("setup", t.setup);
  j.value("step1", t.step1);
  j.value("assembly", t.assembly);
  j.value("factorization", t.factorization);
  j.value("solve", t.solve);
  j.value("metrics", t.metrics);
  j.value("factorizations", t.factorizations);
  j.value("solves", t.solves);
  j.value("cg_iterations", t.cg_iterations);
  j.end_object();
}

void write_patch(JsonWriter& j, const PatchReport& p, double average_edge) {
  j.begin_object();
  j.value("id", p.id);
  j.value("faces", p.faces);
  j.value("vertices", p.vertices);
  j.value("free_vertices", p.free_vertices);
  j.value("tolerance", p.tolerance);
  j.value("tolerance_ae", average_edge > 0 ? p.tolerance / average_edge : 0.0);
  j.value("target_kind", p.target_kind);
  j.value("developability", p.developability);
  j.value("developability_reason", p.developability_reason);
  j.value("fit_residual_deg", p.fit_residual_deg);
  j.value("iterations", p.iterations);
  j.value("stop_reason", p.stop_reason);
  write_figures(j, "before", p.before);
  write_figures(j, "after", p.after);
  j.value("abd_reduction", p.abd_reduction);
  j.value("obd_reduction", p.obd_reduction);
  j.value("time_ms", p.time_ms);
  j.begin_array("history");
  for (const IterationReport& it : p.history) write_iteration(j, it);
  j.end_array();
  j.end_object();
}

const char* name_of(ToleranceMode m) { return m == ToleranceMode::Step ? "step" : "total"; }
const char* name_of(SeamMode m) { return m == SeamMode::Fixed ? "fixed" : "free"; }
const char* name_of(TargetMode m) {
  return m == TargetMode::Fixed ? "fixed" : m == TargetMode::Reproject ? "reproject" : "refit";
}

void write_parameters(JsonWriter& j, const ReportContext& c) {
  const Params& p = c.params;
  j.begin_object("parameters");
  j.value("tolerance", p.tolerance);
  j.value("tolerance_ae", c.options.tolerance_ae);
  j.begin_array("patch_tolerance");
  for (const auto& [id, tolerance] : p.patch_tolerance) {
    j.begin_object();
    j.value("id", id);
    j.value("tolerance", tolerance);
    j.value("tolerance_ae", c.options.patch_tolerance_ae.at(id));
    j.end_object();
  }
  j.end_array();
  j.value("tolerance_mode", std::string(name_of(p.tolerance_mode)));
  j.value("max_iter", p.max_iter);
  j.value("weight", p.weight);
  j.value("anchor", p.anchor);
  j.value("seams", std::string(name_of(p.seams)));
  j.value("keep_boundary", p.keep_boundary);
  j.value("targets", std::string(name_of(p.targets)));
  j.value("stop_abd", p.stop_abd);
  j.value("stop_obd", p.stop_obd);
  j.value("quality",
          std::string(c.options.quality == QualityKind::Curvature ? "curvature" : "displacement"));
  j.end_object();
}

}  // namespace

std::string report_json(const Result& result, const ReportContext& c) {
  JsonWriter j;
  j.begin_object();
  j.value("input", c.options.input);
  j.value("output", c.options.output);
  j.value("vertices", c.vertices);
  j.value("faces", c.faces);
  j.value("has_patch_ids", c.has_patch_ids);
  j.value("constrained_vertices", c.constrained_vertices);
  j.value("average_edge", result.average_edge);
  write_parameters(j, c);
  write_figures(j, "total_before", result.total_before);
  write_figures(j, "total_after", result.total_after);
  j.value("abd_reduction", result.abd_reduction);
  j.value("factorizations", result.factorizations);
  j.value("time_ms", result.time_ms);
  write_times(j, result.times);
  j.begin_array("patches");
  for (const PatchReport& p : result.patches) write_patch(j, p, result.average_edge);
  j.end_array();
  j.begin_array("warnings");
  for (const std::string& warning : result.warnings) j.value(nullptr, warning);
  j.end_array();
  j.begin_array("notes");
  for (const std::string& note : c.notes) j.value(nullptr, note);
  j.end_array();
  j.begin_array("log");
  for (const std::string& line : result.log) j.value(nullptr, line);
  j.end_array();
  j.end_object();
  return j.text();
}

}  // namespace qd::cli
