#include "flatten/flatten_validate.h"

#include <cmath>
#include <string>

#include "common/error.h"
#include "common/format_text.h"
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

void check_params(const FlattenParams& q) {
  if (q.max_iterations < 0 || q.max_iterations > 100000)
    throw Error(
        format_text("The maximum number of ARAP iterations is %d: use a value from 0 (the "
                    "initial layout only) to 100000, e.g. 100.",
                    q.max_iterations));
  if (!std::isfinite(q.tolerance) || q.tolerance < 0 || q.tolerance >= 1)
    throw Error(format_text(
        "The ARAP tolerance is %g: it is a relative change of the energy, use a value in [0, 1), "
        "e.g. 1e-4.",
        q.tolerance));
  if (!std::isfinite(q.gap) || q.gap < 0)
    throw Error(
        format_text("The gap between pieces is %g: use a distance >= 0 (0 = automatic).", q.gap));
  if (!std::isfinite(q.notch_spacing) || q.notch_spacing < 0)
    throw Error(format_text("The notch spacing is %g: use a distance >= 0 (0 = automatic).",
                            q.notch_spacing));
  if (q.threads < 0)
    throw Error(format_text("The number of threads is %d: use 0 (all cores) or more.", q.threads));
}

}  // namespace

void validate_flatten(const FlattenProblem& problem) {
  validate_mesh(problem);
  check_params(problem.params);
}

}  // namespace qd::flatten
