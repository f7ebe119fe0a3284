#include "flatten/flatten_validate.h"

#include <cmath>
#include <sstream>
#include <string>

#include "error.h"
#include "problem.h"
#include "validate.h"

namespace qd {

namespace {

// The mesh checks of the approximation (validate.h) with neutral parameters: nothing
// constrained, so only what makes a mesh unusable fails.
void validate_mesh(const FlattenProblem& problem) {
  Problem check;
  check.V = problem.V;
  check.F = problem.F;
  check.patch = problem.patch;
  check.params.tolerance = 1;
  check.params.seams = SeamMode::Free;
  check.params.keep_boundary = false;
  validate(check);
}

std::string str(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

void check_params(const FlattenParams& q) {
  if (q.max_iterations < 0 || q.max_iterations > 100000)
    throw Error("The maximum number of ARAP iterations is " + std::to_string(q.max_iterations) +
                ": use a value from 0 (the initial layout only) to 100000, e.g. 100.");
  if (!std::isfinite(q.tolerance) || q.tolerance < 0 || q.tolerance >= 1)
    throw Error("The ARAP tolerance is " + str(q.tolerance) +
                ": it is a relative change of the energy, use a value in [0, 1), e.g. 1e-4.");
  if (!std::isfinite(q.gap) || q.gap < 0)
    throw Error("The gap between pieces is " + str(q.gap) + ": use a distance >= 0 (0 = automatic).");
  if (!std::isfinite(q.notch_spacing) || q.notch_spacing < 0)
    throw Error("The notch spacing is " + str(q.notch_spacing) + ": use a distance >= 0 (0 = automatic).");
  if (q.threads < 0)
    throw Error("The number of threads is " + std::to_string(q.threads) + ": use 0 (all cores) or more.");
}

}  // namespace

void validate_flatten(const FlattenProblem& problem) {
  validate_mesh(problem);
  check_params(problem.params);
}

}  // namespace qd
