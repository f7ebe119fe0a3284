// The figures a run of the approximation returns (pymeshlab: the dict of apply_filter). Totals
// are over the whole mesh; percentages as in Eqs. (19)-(20) between the input and the result;
// lengths in model units and in AE; per-patch lists in ascending patch id order. pymeshlab
// 2025.07 drops string values, so the warnings are counted here; their text is in the log.
#pragma once

#include <map>
#include <string>

#include "approximate/result.h"
#include "filter_table.h"

namespace qdml {

std::map<std::string, Figure> result_figures(const qd::approximate::Result& r);

}  // namespace qdml
