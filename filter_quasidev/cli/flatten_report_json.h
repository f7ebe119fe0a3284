// The --report JSON of `quasidev flatten`: what was run (files, mesh size, parameters) and every
// figure of a qd::flatten::FlattenResult (per piece: faces, cut, ARAP iterations and stop reason,
// length distortion, area and boundary change, flips, overlaps, place on the sheet, time), the
// sheet's extent, per pattern piece its label, name, quantity, mirror count, sew and cut line area
// and perimeter and grain direction (the "pattern" array), which pieces each stands for and how
// much they differ, the marker's figures when one was nested, and the log. Input: the result and
// its context. Output: text.
#pragma once

#include <string>
#include <vector>

#include "cut_marker.h"
#include "flatten/flatten_result.h"
#include "options.h"

namespace qd::cli {

struct FlattenReportContext {
  const FlattenOptions& options;
  int vertices;
  int faces;
  bool has_patch_ids;
  const std::vector<std::string>& notes;  // the reader's remarks (e.g. polygons triangulated)
  const marker::MarkerChoice* marker;     // the markers made; null = none asked for
  const std::vector<std::string>& log;    // the engine's log and the command's lines after it
};

std::string flatten_report_json(const flatten::FlattenResult& result,
                                const FlattenReportContext& context);

}  // namespace qd::cli
