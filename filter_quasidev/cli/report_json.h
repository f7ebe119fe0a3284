// The --report JSON: every figure of a qd::approximate::Result (input AE, totals before/after, per
// patch with its per-iteration history and its tolerance in model units and AE, factorisations,
// time) plus what was run (files, mesh size, every declared parameter). Input: the Result and its
// context. Output: text.
#pragma once

#include <string>
#include <vector>

#include "approximate/result.h"
#include "options.h"

namespace qd::cli {

struct ReportContext {
  const ApproximateOptions& options;
  int vertices;
  int faces;
  bool has_patch_ids;
  int constrained_vertices;
  const std::vector<std::string>& notes;  // the reader's remarks (e.g. polygons triangulated)
};

std::string report_json(const approximate::Result& result, const ReportContext& context);

}  // namespace qd::cli
