#include "flatten_report_json.h"

#include "flatten/outline_measures.h"
#include "flatten_params.h"
#include "params_json.h"
#include "report_text.h"

namespace qd::frontend {

namespace {

Json box(const Eigen::AlignedBox2d& b) {
  if (b.isEmpty()) return nullptr;
  return {{"min", {b.min().x(), b.min().y()}}, {"max", {b.max().x(), b.max().y()}}};
}

Json piece(const flatten::PieceReport& p) {
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

// A pattern piece's measures, in model units: areas are the outer loop's less the holes',
// perimeters sum every loop (outline_measures.h).
Json pattern_piece(const flatten::PatternPiece& p, const flatten::PieceGroup& group,
                   const std::vector<flatten::PieceReport>& pieces) {
  Json members = Json::array();
  for (size_t k = 0; k < group.members.size(); ++k)
    members.push_back({{"label", pieces[static_cast<size_t>(group.members[k])].label},
                       {"mirrored", group.mirrored[k] != 0}});
  return {{"label", p.label},
          {"name", p.name},
          {"quantity", p.quantity},
          {"mirrored", p.mirrored},
          {"sew_area", flatten::outline_area(p.outlines)},
          {"sew_perimeter", flatten::outline_length(p.outlines)},
          {"cut_area", flatten::outline_area(p.cut_outlines)},
          {"cut_perimeter", flatten::outline_length(p.cut_outlines)},
          {"grain", {p.grain.x(), p.grain.y()}},
          {"pieces", members},
          {"difference", group.difference}};
}

}  // namespace

Json flatten_report(const flatten::FlattenResult& result, const FlattenReportContext& c) {
  Json pieces = Json::array();
  for (const flatten::PieceReport& p : result.pieces) pieces.push_back(piece(p));
  Json pattern = Json::array();
  for (size_t i = 0; i < result.pattern.pieces.size(); ++i)
    pattern.push_back(pattern_piece(result.pattern.pieces[i], result.groups[i], result.pieces));
  const Json parameters = params::values_json(params::flatten_params(), c.settings);
  const Json report = {{"input", c.input},
                       {"output", c.output},
                       {"vertices", c.vertices},
                       {"faces", c.faces},
                       {"has_patch_ids", c.has_patch_ids},
                       {"parameters", parameters},
                       {"pieces", pieces},
                       {"pattern", pattern},
                       {"max_distortion", result.max_distortion},
                       {"flattenable_pieces", result.flattenable_pieces},
                       {"sheet", box(result.pattern.bounds)},
                       {"time_ms", result.time_ms},
                       {"notes", c.notes},
                       {"log", c.log}};
  return report;
}

}  // namespace qd::frontend
