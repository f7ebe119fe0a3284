#include "segment_report_json.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "params_json.h"
#include "segment/segment_log.h"
#include "segment_params.h"

namespace qd::frontend {

namespace {

using Json = nlohmann::ordered_json;  // keys in the order written

double degrees(double radians) { return radians * 180.0 / M_PI; }

const char* over_limit_name(segment::OverLimit over) {
  switch (over) {
    case segment::OverLimit::No:
      return "";
    case segment::OverLimit::SmallestSize:
      return "smallest_size";
    case segment::OverLimit::SmallPart:
      return "small_part";
    case segment::OverLimit::TargetCount:
      return "target_count";
  }
  return "";
}

Json patch(int id, const segment::SegmentPatch& p, const segment::SegmentParams& q) {
  return {{"id", id},
          {"faces", p.faces},
          {"area", p.area},
          {"proxy",
           {{"kind", segment::proxy_kind(p.proxy)},
            {"axis", {p.proxy.axis.x(), p.proxy.axis.y(), p.proxy.axis.z()}},
            {"angle_deg", degrees(p.proxy.angle)}}},
          {"max_error_deg", p.max_error_deg},
          {"rms_error_deg", p.rms_error_deg},
          {"boundary_loops", p.boundary_loops},
          {"euler", p.euler},
          {"disk", p.disk},
          {"kept", p.kept},
          {"source_patch", p.source_patch},
          {"over_limit", p.over_limit != segment::OverLimit::No},
          {"over_limit_reason", over_limit_name(p.over_limit)},
          {"over_limit_text", segment::over_limit_text(p.over_limit, q)}};
}

}  // namespace

std::string segment_report_json(const segment::SegmentResult& r, const SegmentReportContext& c) {
  Json patches = Json::array();
  for (std::size_t id = 0; id < r.patches.size(); ++id)
    patches.push_back(patch(static_cast<int>(id), r.patches[id], c.settings.engine));
  const Json parameters = params::values_json(params::segment_params(), c.settings);
  const Json report = {{"input", c.input},
                       {"output", c.output},
                       {"vertices", c.vertices},
                       {"faces", c.faces},
                       {"has_patch_ids", c.has_patch_ids},
                       {"selected_faces", c.selected_faces},
                       {"parameters", parameters},
                       {"patch_count", static_cast<int>(r.patches.size())},
                       {"rounds", r.rounds},
                       {"time_ms", r.time_ms},
                       {"patches", patches},
                       {"warnings", r.warnings},
                       {"notes", c.notes},
                       {"log", r.log}};
  // NaN and infinities are written as null; bytes that are not UTF-8 as U+FFFD.
  return report.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace qd::frontend
