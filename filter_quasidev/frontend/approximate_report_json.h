// The approximation's JSON report (the command's --report, the Python module's report): every
// figure of a qd::approximate::Result (input AE, totals before/after, per patch with its
// per-iteration history and its tolerance in model units and AE, factorisations, time) plus what
// was run (files, mesh size, every declared parameter). Input: the Result and its context.
// Output: text.
#pragma once

#include <string>
#include <vector>

#include "approximate/result.h"
#include "approximate_settings.h"

namespace qd::frontend {

struct ReportContext {
  const std::string& input;  // the files, as given ("" when there is none)
  const std::string& output;
  const params::ApproximateSettings& settings;
  int vertices;
  int faces;
  bool has_patch_ids;
  int constrained_vertices;
  const std::vector<std::string>& notes;  // the reader's remarks (e.g. polygons triangulated)
};

std::string report_json(const approximate::Result& result, const ReportContext& context);

}  // namespace qd::frontend
