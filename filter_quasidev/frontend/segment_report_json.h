// The segmentation's JSON report (the --report of `quasidev segment`, the Python module's report):
// what was run (files, mesh size, parameters) and every figure of a qd::segment::SegmentResult: per
// patch its faces, area, fitted proxy (kind, axis, apex angle), fit error max/rms in degrees,
// boundary loops, Euler characteristic, disk or not, and why it is over the limit; the warnings and
// the log. Input: the result and its context.
#pragma once

#include <string>
#include <vector>

#include "segment/segment_result.h"
#include "segment_settings.h"

namespace qd::frontend {

struct SegmentReportContext {
  const std::string& input;  // the files, as given ("" when there is none)
  const std::string& output;
  const params::SegmentSettings& settings;
  int vertices;
  int faces;
  bool has_patch_ids;  // the input has patch ids (used only with --keep-patches)
  int selected_faces;
  const std::vector<std::string>& notes;  // the reader's remarks (e.g. polygons triangulated)
};

std::string segment_report_json(const segment::SegmentResult& result,
                                const SegmentReportContext& context);

}  // namespace qd::frontend
