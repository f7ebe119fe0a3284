// Step 1 per patch of a solve group (paper §5.1) and what it gives the deformation: the fitted
// Gauss-image model, the developability term each patch takes, the target normals, the
// re-projection between iterations and the vertices that get angle-defect rows.
#pragma once

#include <string>
#include <vector>

#include "approximate/deformer.h"
#include "approximate/group_mesh.h"
#include "approximate/params.h"
#include "approximate/result.h"
#include "approximate/target_normals.h"

namespace qd::approximate {

// Below this fit residual a planar patch is already developable: nothing to do.
constexpr double kPlanarResidualDeg = 0.05;

// Why a patch takes its term.
enum class TermReason { AsAsked, Planar, TooSmall, NoCurveFits, Measured, Given };

struct PatchFit {
  int id = 0;
  std::vector<int> faces;  // local faces of the group
  TargetFit fit;
  std::string skipped;  // why Step 1 failed; empty when it succeeded
  Term term = Term::None;
  TermReason reason = TermReason::AsAsked;
  bool after_curve = false;  // Measured: the angle-defect rows ran after the curve term alone
                             // removed nothing (group_run.cpp)
  bool fitted() const { return skipped.empty(); }
  bool planar() const;
  bool idle() const { return term == Term::None; }
};

// Step 1 for every patch of the group at positions X (projections on up to `threads` threads).
// A patch too small to fit or one Step 1 cannot fit keeps its own normals as targets.
std::vector<PatchFit> fit_patches(const GroupMesh& g, const Positions& X, size_t threads);

// The term of a patch for the parameter; Auto leaves Term::None on a patch that can move, for
// the race (term_race.h) to decide. Curve is the paper's; the angle defects need no fit, so
// they also take patches whose normals fill the sphere.
void choose_term(PatchFit& p, Developability mode);

// Above this many vertices in its solve group, a patch whose curve fits races no candidate
// with angle-defect rows: those are always factorised (deformation_system.h), while the curve
// term's conjugate gradients (from 10,000 unknowns) never factorise, and the defect candidate's
// factorisation would then dominate the race (docs/measurements-behind-the-code.md). The
// garments' panels and the robustness sweep's members are all below the bound, so they race.
// Above it, where the curve term removes nothing, the angle-defect rows run after it
// (group_run.cpp).
constexpr Eigen::Index kMaxDefectRaceVertices = 25000;

// The candidate terms of Developability::Auto for a patch of a group with `vertices` vertices:
// Curve and Both where a curve fits, Defect where the group is not too large for it.
std::vector<Term> candidate_terms(const PatchFit& p, Eigen::Index vertices);

// Target per group face for the patches' terms; zero (no Eq. 13 rows) on defect-only faces.
std::vector<Vec3> group_targets(const GroupMesh& g, const std::vector<PatchFit>& fits);

// Re-projection (nearest point of the fixed c_3D) or re-fit (Step 1 again, each patch keeping
// its term) between iterations, on up to `threads` threads. Keeps references to g and fits.
Retarget make_retarget(const GroupMesh& g, const std::vector<PatchFit>& fits, size_t threads);

// Whether a run on these fits that stalls fits its curves again (deformer.h): asked for
// (TargetMode::ReprojectThenRefit under the Plateau rule), and some patch takes the curve rows
// of a fitted Gauss-image model that is not already a plane it lies in.
bool refits_when_stalled(const std::vector<PatchFit>& fits, const Params& params);

// Per local vertex, 1 = an angle-defect row: the free interior vertices that touch a face of
// a patch with defect rows (empty when there is none).
std::vector<char> group_defect_rows(const GroupMesh& g, const std::vector<PatchFit>& fits);

}  // namespace qd::approximate
