#include "flatten/flatten_validate.h"

#include <cmath>
#include <sstream>
#include <string>

#include "common/error.h"
#include "common/validate_mesh.h"
#include "flatten/common_names.h"

namespace qd::flatten {

namespace {

// The mesh checks every job shares (common/validate_mesh.h); patches of any size can be
// flattened, so the approximation's patch checks do not apply.
void validate_mesh(const FlattenProblem& problem) {
  check_not_empty(problem.V, problem.F);
  if (!problem.patch.empty() && problem.patch.size() != static_cast<size_t>(problem.F.rows()))
    throw Error("The patch ids are " + std::to_string(problem.patch.size()) + " for " +
                std::to_string(problem.F.rows()) + " faces: give one patch id per face, or none.");
  check_coordinates(problem.V);
  check_face_indices(problem.F, static_cast<int>(problem.V.rows()));
  check_zero_area(problem.V, problem.F);
  const Topology topology =
      analyse_topology(problem.F, static_cast<int>(problem.V.rows()), problem.patch);
  check_duplicate_faces(topology);
  check_orientation(topology);
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
    throw Error("The gap between pieces is " + str(q.gap) +
                ": use a distance >= 0 (0 = automatic).");
  if (!std::isfinite(q.notch_spacing) || q.notch_spacing < 0)
    throw Error("The notch spacing is " + str(q.notch_spacing) +
                ": use a distance >= 0 (0 = automatic).");
  if (q.threads < 0)
    throw Error("The number of threads is " + std::to_string(q.threads) +
                ": use 0 (all cores) or more.");
}

}  // namespace

void validate_flatten(const FlattenProblem& problem) {
  validate_mesh(problem);
  check_params(problem.params);
}

}  // namespace qd::flatten
