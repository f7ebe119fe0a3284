// The print settings of the command as page geometry: the paper's size in points (ISO 216 A4,
// 210 x 297 mm; US Letter, 8.5 x 11 in) and the model unit's length on paper.
#pragma once

#include "choices.h"
#include "page_tiles.h"

namespace qd::pdf {

// Portrait `paper` with the default margin and overlap.
PageSpec page_spec(params::Paper paper);

// Points per model unit; throws qd::common::Error for PatternUnit::Model (no physical size).
double points_per_unit(params::PatternUnit unit);

}  // namespace qd::pdf
