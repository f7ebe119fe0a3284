// The --report JSON of `quasidev flatten`: the flattening's report (frontend/flatten_report_json.h)
// and, when a marker was nested, the kept marker's figures (width, length, efficiency, pieces
// placed and not), which placement it is, and both placements' figures. Output: text.
#pragma once

#include <string>

#include "cut_marker.h"
#include "flatten_report_json.h"

namespace qd::cli {

// marker: the markers made; null = none asked for.
std::string flatten_report_json(const flatten::FlattenResult& result,
                                const frontend::FlattenReportContext& context,
                                const marker::MarkerChoice* marker);

}  // namespace qd::cli
