// The approximation's parameters, in the MeshLab dialog's order. Defaults: qd::approximate::Params
// and ApproximateSettings.
#include "approximate_params.h"

#include "approximate/deformation_system.h"
#include "common/format_text.h"
#include "common/solver_kind.h"
#include "declare.h"

namespace qd::params {

namespace {

using S = ApproximateSettings;

std::string solver_help() {
  return "The sparse Cholesky back end: cholmod (SuiteSparse's supernodal LLT), eigen-llt or "
         "eigen-ldlt (Eigen's simplicial), or auto (eigen-ldlt below " +
         std::to_string(common::kCholmodFromUnknowns) +
         " unknowns per patch, else our supernodal LDLT on SuiteSparse's analysis); the result is "
         "the same. Patches with angle-defect rows solve their quasi-definite system by LDLT: our "
         "supernodal one (auto, cholmod) or Eigen's simplicial one (eigen-llt, eigen-ldlt).";
}

std::string method_help() {
  return common::format_text(
      "direct: factorise each patch's coupled system; iterative: conjugate gradients with two "
      "scalar factors, to a relative error of %g, or, where they converge too slowly for that "
      "within %d iterations, as far as they got; auto: iterative from %ld unknowns per patch. "
      "Patches with angle-defect rows are always factorised.",
      approximate::kCgTolerance, approximate::kCgIterations, approximate::kIterativeFromUnknowns);
}

std::vector<Param<S>> declare() {
  using P = Params;
  return {
      real("tolerance_ae", field(&S::tolerance_ae), Unit::AverageEdge, greater_than(0),
           "Tolerance (AE)",
           "delta_err, the most a vertex may move in one iteration (tolerance_mode step) or in all "
           "(total), in units of AE, the input's average edge length. Smaller keeps the shape "
           "closer but leaves more curvature. tolerance_model, when above 0, replaces it.")
          .alias("--tolerance"),
      real("tolerance_model", field(&S::tolerance_model), Unit::ModelUnits, at_least(0),
           "Tolerance (model units)",
           "delta_err in model units instead of AE; 0 = use tolerance_ae."),
      text<S>(
          "patch_tolerance_ae", "ID=X[,ID=X...]", Unit::AverageEdge,
          [](const S& s) { return patch_tolerance_text(s.patch_tolerance_ae); },
          [](S& s, const std::string& t) { parse_patch_tolerance(t, s.patch_tolerance_ae); },
          "Per-patch tolerance (AE)",
          "delta_err of single patches, in AE, replacing the tolerance there: patch id = value "
          "pairs separated by commas, e.g. 3=0.05,7=2 (the command's option may also be given "
          "once per patch); empty = none.")
          .alias("--patch-tolerance"),
      choice("tolerance_mode", field(&S::engine, &P::tolerance_mode), kToleranceModes,
             "Tolerance mode",
             "step: the tolerance caps each iteration's move (the paper); total: it caps the whole "
             "move from the input."),
      choice("clamp", field(&S::engine, &P::clamp), kClampModes, "Step limit",
             "How step mode keeps each move within the tolerance: scale shrinks the whole step so "
             "no vertex moves more (it stays a least-squares step); vertex clamps each vertex's "
             "step on its own (the paper, Sec. 5.2). Total mode always clamps per vertex."),
      integer("max_iter", field(&S::engine, &P::max_iter), Unit::Iterations, closed(1, 10000),
              "Max iterations",
              "Stop after this many iterations per patch (the paper's maxIter); the plateau stop "
              "rule ends most runs sooner."),
      choice("stop_rule", field(&S::engine, &P::stop_rule), kStopRules, "Stop rule",
             "plateau: stop when the last 3 iterations together lowered G_ABD by less than "
             "stop_abd, and keep the best iterate (beyond the paper); paper: stop at the first "
             "iteration whose ratio_ABD (Eq. 19) is below stop_abd, or ratio_OBD (Eq. 20) below "
             "stop_obd with fixed targets (Sec. 5.4)."),
      real("stop_abd", field(&S::engine, &P::stop_abd), Unit::Percent, below(0, 100),
           "Stop at ratio_ABD (%)",
           "delta_ABD: with the plateau rule, the least share of G_ABD (the total absolute "
           "Gaussian curvature) the last 3 iterations must remove for the run to go on; with the "
           "paper's rule, the least ratio_ABD (Eq. 19) of one iteration."),
      real("stop_obd", field(&S::engine, &P::stop_obd), Unit::Percent, below(0, 100),
           "Stop at ratio_OBD (%)",
           "delta_OBD: with the paper's stop rule and fixed targets, stop when an iteration lowers "
           "the orientation developability D(P) by less than this percentage (ratio_OBD, Eq. 20)."),
      real("weight", field(&S::engine, &P::weight), Unit::None, greater_than(0),
           "Developability weight",
           "w of the paper's Eq. (8): how strongly faces turn towards their target normals "
           "against keeping their shape. Larger removes more curvature per iteration but moves "
           "more."),
      choice("developability", field(&S::engine, &P::developability), kDevelopability,
             "Developability term",
             "Which rows make each patch developable. curve: the paper's target normals on the "
             "curve fitted to the patch's Gauss image (best for cones, cylinders, lampshades, "
             "sleeves); defect: Gauss-Newton rows that drive every interior angle defect to zero "
             "(beyond the paper; best for draped, wrinkled panels whose Gauss image is a blob); "
             "both; auto: per patch, the three race from the same start and the one that removes "
             "most G_ABD is kept (beyond the paper). The log gives each candidate's figures."),
      real("defect_weight", field(&S::engine, &P::defect_weight), Unit::None, greater_than(0),
           "Angle-defect weight",
           "w_d of the angle-defect rows against keeping the shape; scale- and density-invariant. "
           "Larger removes more curvature per iteration but moves the surface more."),
      real("anchor", field(&S::engine, &P::anchor), Unit::None, at_least(0), "Anchor stiffness",
           "alpha of the soft anchors (paper Eq. 15): how strongly vertices near fixed vertices "
           "resist moving; the stiffness fades with the distance (in AE) from fixed vertices."),
      choice("target_mode", field(&S::engine, &P::targets), kTargetModes, "Target normals",
             "fixed: fit the Gauss-image curve once (the paper); reproject: project the current "
             "normals onto it every iteration; refit: refit the curve every iteration (slower); "
             "reproject-then-refit (default): reproject, and where that stalls (a plateau, or no "
             "step), fit the curve again and refit from there on, once (a run never removes less "
             "than with reproject; where it stalls it runs at least 3 iterations more).")
          .alias("--targets"),
      choice("seam_mode", field(&S::engine, &P::seams), kSeamModes, "Seams",
             "fixed: vertices shared by two patches do not move (the paper), except where a patch "
             "mostly on seams is solved with its neighbour (the log names it); free: all patches "
             "are solved together and seam vertices move too, staying shared so no crack opens.")
          .alias("--seams"),
      choice("segment_first", field(&S::engine, &P::segment_first), kSegmentFirst, "Segment first",
             "A mesh without patch ids: auto splits it into nearly developable patches first "
             "(segmentation, largest fit error 30 degrees) and solves them with free seams when it "
             "is closed or no one Gauss-image curve fits it; never keeps it one patch; always "
             "splits it."),
      boolean("keep_boundary", field(&S::engine, &P::keep_boundary), "Keep boundary",
              "The vertices of the open mesh boundary do not move.")
          .off_alias("--free-boundary"),
      boolean("use_patches", field(&S::use_patches), "Patches from the input",
              "Faces with the same patch id (MeshLab: per-face quality, rounded; the command: PLY "
              "face quality or patch, OBJ groups) form one patch, each made developable on its "
              "own. Off, or without patch ids: the whole mesh is one patch."),
      choice("solver", field(&S::engine, &P::solver), kSolverKinds, "Sparse solver", solver_help())
          .only(kCommand, kSpeedOnly),
      choice("method", field(&S::engine, &P::method), kSolveMethods, "Solve method", method_help())
          .only(kCommand, kSpeedOnly),
      threads(field(&S::engine, &P::threads),
              "Patches solved at once (fixed seams; a lone patch uses them inside); 0 = all cores. "
              "The result does not depend on it."),
      choice("output_quality", field(&S::output_quality), kQualityKinds, "Output quality",
             "What the per-vertex quality holds afterwards: curvature, the Gaussian curvature K "
             "after the filter, or displacement, each vertex's move |v' - v| in model units.")
          .alias("--quality"),
      boolean(
          "colorize", field(&S::colorize), "Colorize",
          "Colour the vertices by a ramp on the output quality (red low, blue high, range = its "
          "2nd to 98th percentile); off keeps the input's vertex colours.")
          .off_alias("--no-color"),
      text<S>(
          "constraints_file", "FILE", Unit::None, [](const S& s) { return s.constraints_file; },
          [](S& s, const std::string& t) { s.constraints_file = t; }, "Fixed vertices file",
          "Vertices that must not move, as a text file of 0-based vertex indices, one per line; "
          "'#' starts a comment. They are added to the input's selected vertices.")
          .alias("--constraints")
          .only(kCommand,
                "In MeshLab the selected vertices are the fixed ones: select them (Filters > "
                "Selection, or by hand) before running the filter."),
  };
}

}  // namespace

const std::vector<Param<ApproximateSettings>>& approximate_params() {
  static const std::vector<Param<ApproximateSettings>> params = declare();
  return params;
}

}  // namespace qd::params
