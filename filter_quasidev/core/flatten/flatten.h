// The flattening's entry point (docs/design.md "Beyond the paper": segment → approximate →
// flatten): every patch of a mesh becomes a pattern piece, cut to a disk where it is not one,
// flattened as rigidly as possible (ARAP, Liu et al. 2008), placed on one sheet at true scale,
// measured (docs/design.md "Metrics": Flattening) and drawn as a pattern for the SVG/DXF
// writers. A patch too far from developable is flattened anyway, with its distortion, flips and
// overlaps reported.
#pragma once

#include "common/progress.h"
#include "flatten/common_names.h"
#include "flatten/flatten_problem.h"
#include "flatten/flatten_result.h"

namespace qd::flatten {

// Throws qd::common::Error on bad input (validate.h) or a piece that cannot be flattened; the input
// is never modified. Pieces are flattened in parallel; the result does not depend on the number of
// threads.
FlattenResult flatten(const FlattenProblem& problem, const Progress& progress = {});

}  // namespace qd::flatten
