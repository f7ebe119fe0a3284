// The mesh checks every job shares (common/validate_mesh.h), the sizes of the per-face inputs and
// the parameters of the segmentation.
#include "segment/segment_validate.h"

#include <cmath>
#include <limits>
#include <string>

#include "common/error.h"
#include "common/message_text.h"
#include "common/topology.h"
#include "common/validate_mesh.h"
#include "segment/common_names.h"

namespace qd::segment {

namespace {

template <typename T>
void check_per_face(const std::vector<T>& values, const Triangles& F, const char* what) {
  if (!values.empty() && values.size() != static_cast<size_t>(F.rows()))
    throw Error("Got " + std::to_string(values.size()) + " " + what + " for " +
                std::to_string(F.rows()) + " faces: give one per face, or none.");
}

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

// x in [lo, hi] (or (lo, hi] when lo_open); hi = kNoLimit for no upper limit.
void check_range(const char* name, double x, double lo, double hi, bool lo_open, const char* hint) {
  const bool ok = std::isfinite(x) && (lo_open ? x > lo : x >= lo) && x <= hi;
  if (ok) return;
  const std::string range = hi == kNoLimit ? "of at least " + to_text(lo)
                                           : std::string("in ") + (lo_open ? "(" : "[") +
                                                 to_text(lo) + ", " + to_text(hi) + "]";
  throw Error(std::string("The ") + name + " is " + to_text(x) + ": use a value " + range + ", " +
              hint + ".");
}

void check_params(const SegmentParams& q) {
  check_range("largest fit error", q.max_error_deg, 0, 90, true, "in degrees, e.g. 20");
  check_range("smallest patch size", q.min_faces, 1, kNoLimit, false, "in faces, e.g. 20");
  check_range("smallest patch area", q.min_area, 0, 1, false,
              "as a fraction of the mesh area, e.g. 0.001 (0 = no area limit)");
  check_range("target patch count", q.target_patches, 0, kNoLimit, false,
              "e.g. 0 for as many as the fit needs");
  check_range("crease angle", q.crease_deg, 0, 180, true, "in degrees, e.g. 60 (180 = none)");
  check_range("fitting weight", q.weights.fit, 0, 10, false, "e.g. 1");
  check_range("compactness weight", q.weights.compactness, 0, 10, false, "e.g. 0.5");
  check_range("boundary weight", q.weights.boundary, 0, 10, false, "e.g. 2");
  check_range("number of Lloyd rounds", q.max_rounds, 1, 1000, false, "e.g. 10");
  check_range("number of threads", q.threads, 0, 1024, false, "e.g. 0 for all cores");
}

}  // namespace

void validate_segment(const SegmentProblem& p) {
  check_not_empty(p.V, p.F);
  check_per_face(p.patch, p.F, "patch ids");
  check_per_face(p.selected, p.F, "selection flags");
  check_coordinates(p.V);
  check_face_indices(p.F, static_cast<int>(p.V.rows()));
  check_zero_area(p.V, p.F);
  check_params(p.params);
  check_duplicate_faces(analyse_topology(p.F, static_cast<int>(p.V.rows()), {}));
}

}  // namespace qd::segment
