// The figures a run of the flattening returns (pymeshlab: the dict of apply_filter): totals, and
// one list per figure with an entry per pattern piece, in the engine's order (by patch id, then
// component). Percentages as in flatten/piece_measures.h; lengths in model units. pymeshlab
// 2025.07 drops string values, so the pieces' cut notes are flags here; their text is in the log.
#pragma once

#include <map>
#include <string>

#include "filter_table.h"
#include "flatten/flatten_result.h"

namespace qdml {

std::map<std::string, Figure> flatten_figures(const qd::flatten::FlattenResult& r);

}  // namespace qdml
