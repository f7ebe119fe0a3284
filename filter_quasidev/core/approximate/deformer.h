// Step 2 of Algorithm 1 (paper §5.4) for one group: iterate solve → clamp to δ_err → accept,
// with the three stop criteria (maxIter, ratio_ABD < δ_ABD, ratio_OBD < δ_OBD; Eqs. 19–20) and
// the never-worse rule (beyond the paper): a step that raises G_ABD or flips a face is halved,
// and if no shortened step helps, the iteration is rejected and the group stops. With
// angle-defect rows, a step that folds faces is first tried with their vertices held back.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "approximate/group_mesh.h"
#include "approximate/params.h"
#include "approximate/result.h"
#include "common/progress.h"

namespace qd {

// New target normal per group face for the current positions (re-projection or re-fit).
using Retarget = std::function<std::vector<Vec3>(const Positions& current)>;

struct DeformOutcome {
  Positions V;                        // final local positions
  std::vector<IterationReport> history;
  std::string stop_reason;
  StageTimes times;                   // assembly, factorisation, solve, re-targeting, metrics
};

// targets: initial target per group face (zero: no Eq. 13 developability rows for it);
// retarget: used between iterations unless params.targets == TargetMode::Fixed; defect_rows:
// per local vertex, 1 = an angle-defect row (angle_defect.h; empty = none), linearised again
// before every solve; progress receives
// the fraction of max_iter done.
DeformOutcome deform(const GroupMesh& group, const std::vector<Vec3>& targets,
                     const Retarget& retarget, const std::vector<char>& defect_rows, const Params& params,
                     double ae, const std::function<void(double)>& progress);

// Limits the step from `current` to `proposed` by the group's δ_err (§5.2). Step mode:
// |Δv| ≤ δ_err for every vertex, by scaling the whole step (ClampMode::Scale) or clamping each
// vertex (ClampMode::Vertex, the paper's). Total mode: |v' − v0| ≤ δ_err, vertex by vertex.
Positions clamp_step(const GroupMesh& group, const Positions& current, const Positions& proposed,
                     ToleranceMode mode, ClampMode clamp);

// Number of faces whose normal at V points against their normal at V0 (or became degenerate).
int flipped_faces(const Triangles& F, const Positions& V0, const Positions& V);

}  // namespace qd
