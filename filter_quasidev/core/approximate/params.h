// User parameters of the quasi-developable approximation (docs/design.md "The algorithm").
// Lengths are in model units; adapters convert from multiples of the average edge length AE.
#pragma once

#include <map>

#include "approximate/common_names.h"
#include "common/solver_kind.h"

namespace qd::approximate {

enum class SeamMode { Fixed, Free };       // seam vertices fixed (paper) or shared unknowns
enum class ToleranceMode { Step, Total };  // δ_err caps each step (paper) or the total move
// δ_err in Step mode: scale the whole step, or clamp each vertex's step (paper §5.2).
enum class ClampMode { Scale, Vertex };
// Targets fitted once (the paper), re-projected, re-fitted, or re-projected until they stall and
// re-fitted from there (deformer.h).
enum class TargetMode { Fixed, Reproject, Refit, ReprojectThenRefit };
// When Step 2 stops (deformer.h): when the best G_ABD fell by less than δ_ABD over the last
// few iterations (beyond the paper), or at the first iteration below δ_ABD / δ_OBD (§5.4).
enum class StopRule { Plateau, Paper };
// A mesh without patch ids split into patches first (segment_first.h): when it is closed or
// no one Gauss-image curve fits it (Auto), never, or always.
enum class SegmentFirst { Auto, Never, Always };
enum class SolveMethod { Auto, Direct, Iterative };  // factorise M, or CG with scalar factors
// Developability term per patch: the paper's normal targets on the Gauss-image curve (Eq. 13),
// Gauss–Newton rows on the angle defects (angle_defect.h, beyond the paper), both, or chosen
// per patch from its Step 1 fit residual (Auto, beyond the paper).
enum class Developability { Curve, Defect, Both, Auto };

struct Params {
  double tolerance = 0.0;                 // δ_err in model units (> 0)
  std::map<int, double> patch_tolerance;  // per patch id, overrides tolerance
  ToleranceMode tolerance_mode = ToleranceMode::Step;
  ClampMode clamp = ClampMode::Scale;  // Step mode only; Total mode clamps per vertex
  int max_iter = 30;                   // stop criterion 1 (the plateau stops most runs sooner)
  double weight = 30.0;                // w of Eq. (8): developability vs shape rows
  Developability developability = Developability::Auto;
  double defect_weight = 0.03;  // w_d of the angle-defect rows (angle_defect.h)
  double anchor = 3.0;          // α of the MLS soft anchor rows (Eq. 15)
  SeamMode seams = SeamMode::Fixed;
  SegmentFirst segment_first = SegmentFirst::Auto;  // meshes without patch ids
  bool keep_boundary = true;                        // open mesh boundary vertices are constrained
  TargetMode targets = TargetMode::ReprojectThenRefit;
  StopRule stop_rule = StopRule::Plateau;
  double stop_abd = 1.0;                 // δ_ABD, percent (Eq. 19)
  double stop_obd = 1.0;                 // δ_OBD, percent (Eq. 20)
  SolverKind solver = SolverKind::Auto;  // Auto: by size, as measured (positive_definite_factor.h)
  SolveMethod method = SolveMethod::Auto;  // Auto: by size, as measured (deformation_system.h)
  int threads = 0;                         // patches solved at once (a lone patch uses them
                                           // inside); 0 = all cores
};

}  // namespace qd::approximate
