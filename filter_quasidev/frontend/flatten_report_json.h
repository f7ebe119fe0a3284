// The flattening's JSON report (the --report of `quasidev flatten`, the Python module's report)
// without the marker's figures (the command adds them: cli/marker_report_json.h): what was run
// (files, mesh size, parameters) and every figure of a qd::flatten::FlattenResult (per piece:
// faces, cut, ARAP iterations and stop reason, length distortion, area and boundary change,
// flips, overlaps, place on the sheet, time), the sheet's extent, per pattern piece its label,
// name, quantity, mirror count, sew and cut line area and perimeter and grain direction (the
// "pattern" array), which pieces each stands for and how much they differ, and the log. Input:
// the result and its context. Output: a JSON object.
#pragma once

#include <string>
#include <vector>

#include "flatten/flatten_result.h"
#include "flatten_settings.h"
#include "report_text.h"

namespace qd::frontend {

struct FlattenReportContext {
  const std::string& input;  // the files, as given ("" when there is none)
  const std::string& output;
  const params::FlattenSettings& settings;
  int vertices;
  int faces;
  bool has_patch_ids;
  const std::vector<std::string>& notes;  // the reader's remarks (e.g. polygons triangulated)
  const std::vector<std::string>& log;    // the engine's log and the command's lines after it
};

Json flatten_report(const flatten::FlattenResult& result, const FlattenReportContext& context);

}  // namespace qd::frontend
