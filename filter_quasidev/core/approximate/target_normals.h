// Step 1 of the paper (§5.1) for one patch: from the DEGI (unit face normals weighted by
// face area) to the spherical skeleton curve c_3D and the target normal of every face.
#pragma once

#include <memory>
#include <vector>

#include "approximate/common_names.h"
#include "approximate/result.h"
#include "common/mesh.h"

namespace qd::approximate {

// The fitted Gauss-image model of one patch: the spherical curve c_3D, or a single
// direction when the Gauss image is a point (planar patch).
class GaussModel {
 public:
  virtual ~GaussModel() = default;
  // Nearest point of the model to the unit vector n (angular distance), refined below
  // the sampling step of the curve. Result is a unit vector.
  Vec3 project(const Vec3& n) const {
    int hint = -1;
    return project(n, hint);
  }
  // The same, with the search starting from `hint`: -1, or the value a projection of a nearby
  // vector left in it (projecting the normals of neighbouring faces one after another spares
  // the global search). The result does not depend on the hint.
  virtual Vec3 project(const Vec3& n, int& hint) const = 0;
  // Curve, ClosedCurve or Plane.
  virtual TargetKind kind() const = 0;
};

struct TargetFit {
  std::shared_ptr<const GaussModel> model;
  std::vector<Vec3> targets;  // one unit target normal per input normal
  double residual_deg = 0;    // area-weighted mean angle between normal and target
};

// The model's nearest point to each unit normal (Step 1.5), projected in ranges on up to
// `threads` threads; the result does not depend on them.
std::vector<Vec3> project_normals(const GaussModel& model, const std::vector<Vec3>& normals,
                                  size_t threads);

// Steps 1.1–1.4 alone: the model fitted to the samples (normals[i] unit, areas[i] >= 0), no
// target projected. Throws as fit_targets does.
std::shared_ptr<const GaussModel> fit_model(const std::vector<Vec3>& normals,
                                            const std::vector<double>& areas);

// Fits the model to the samples (normals[i] unit, areas[i] >= 0) and projects every sample
// (on up to `threads` threads). Throws qd::common::Error when the samples fill the sphere (far from
// developable) or are too few.
TargetFit fit_targets(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                      size_t threads = 1);

}  // namespace qd::approximate
