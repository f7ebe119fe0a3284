#include "marker_report_json.h"

namespace qd::cli {

namespace {

using frontend::Json;

Json marker_json(const marker::Marker& m) {
  return {{"width", m.width},
          {"length", m.length},
          {"efficiency", m.efficiency},
          {"placed", m.placements.size()},
          {"unplaced", m.unplaced}};
}

// The kept marker's figures, which placement it is, and both placements' figures.
Json marker_json(const marker::MarkerChoice& c) {
  Json j = marker_json(c.kept());
  j["method"] = c.nested_kept ? "nested" : "rows";
  j["nested"] = marker_json(c.nested);
  j["rows"] = marker_json(c.rows);
  return j;
}

}  // namespace

std::string flatten_report_json(const flatten::FlattenResult& result,
                                const frontend::FlattenReportContext& context,
                                const marker::MarkerChoice* marker) {
  Json report = frontend::flatten_report(result, context);
  if (marker) report["marker"] = marker_json(*marker);
  return frontend::report_text(report);
}

}  // namespace qd::cli
