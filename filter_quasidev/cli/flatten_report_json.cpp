#include "flatten_report_json.h"

#include "flatten_params.h"
#include "params_json.h"
#include "report_text.h"

namespace qd::cli {

namespace {

Json box(const Eigen::AlignedBox2d& b) {
  if (b.isEmpty()) return nullptr;
  return {{"min", {b.min().x(), b.min().y()}}, {"max", {b.max().x(), b.max().y()}}};
}

Json piece(const PieceReport& p) {
  return {{"patch", p.patch},
          {"component", p.component},
          {"label", p.label},
          {"faces", p.faces},
          {"vertices", p.vertices},
          {"cut", p.cut},
          {"iterations", p.iterations},
          {"stop_reason", p.stop_reason},
          {"energy", p.energy},
          {"max_distortion", p.max_distortion},
          {"mean_distortion", p.mean_distortion},
          {"area_change", p.area_change},
          {"boundary_change", p.boundary_change},
          {"flipped", p.flipped},
          {"overlapping", p.overlapping},
          {"flattenable", p.flattenable},
          {"box", box(p.box)},
          {"time_ms", p.time_ms}};
}

}  // namespace

std::string flatten_report_json(const FlattenResult& result, const FlattenReportContext& c) {
  Json pieces = Json::array();
  for (const PieceReport& p : result.pieces) pieces.push_back(piece(p));
  const Json parameters = params::values_json(params::flatten_params(), c.options.settings);
  const Json report = {{"input", c.options.input},
                       {"output", c.options.output},
                       {"vertices", c.vertices},
                       {"faces", c.faces},
                       {"has_patch_ids", c.has_patch_ids},
                       {"parameters", parameters},
                       {"pieces", pieces},
                       {"max_distortion", result.max_distortion},
                       {"flattenable_pieces", result.flattenable_pieces},
                       {"sheet", box(result.pattern.bounds)},
                       {"time_ms", result.time_ms},
                       {"notes", c.notes},
                       {"log", result.log}};
  return report_text(report);
}

}  // namespace qd::cli
