// Checks of a flattening problem before any work (docs/design.md "Bad input"): the mesh checks of
// the approximation (validate.h) and the flattening's own parameters. Throws qd::common::Error with
// a message that says what was wrong and what to do.
#pragma once

#include "flatten/flatten_problem.h"

namespace qd::flatten {

void validate_flatten(const FlattenProblem& problem);

}  // namespace qd::flatten
