// Output of the engine: new positions, per-vertex figures, per-patch and total reports.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "approximate/common_names.h"
#include "common/mesh.h"
#include "common/metrics.h"

namespace qd::approximate {

// The developability rows a patch gets: the paper's normal targets (Eq. 13), the angle-defect
// rows (angle_defect.h), both, or none (planar, too small, or not fitted with Curve asked).
enum class Term { None, Curve, Defect, Both };

// Why a patch took its term, as reported (report_text.h words it).
enum class TermChoice {
  AsAsked,          // the parameter named it
  Planar,           // already developable
  TooSmall,         // too few faces to fit
  NoCurveFits,      // Curve asked, and no Gauss-image curve fits
  EarlierPass,      // Auto: decided by the race of an earlier pass
  AutoNoCurveFits,  // Auto: no curve fits, so the defect rows
  AutoNotRaced,     // Auto: above kMaxDefectRaceVertices, the curve term without a race
  AutoAfterCurve,   // Auto: above it, the defect rows too where the curve term removed nothing
  Auto,             // Auto: the only candidate
  AutoMeasured      // Auto: the race's winner (candidates hold its figures)
};

// The Step 1 model a patch's targets come from (target_normals.h): the Gauss-image curve, open
// or closed, a single direction (planar), or none (the faces keep their normals).
enum class TargetKind { Curve, ClosedCurve, Plane, Unchanged };

// The passes of a solve (solve_schedule.h): one with fixed seams, three with free seams.
enum class SolvePass { Only, AllAtOnce, SeamsHeld, SeamsFree };

// Why a patch's run in one pass stopped: the deformer's stop rules (deformer.h), or nothing to
// do (Planar, or Unfitted: Step 1 found no model).
// MoveBound: auto's stronger rows, kept, stopped where an iterate moved further than their bound
// (group_run.h).
enum class PatchStop { MaxIter, Plateau, RatioAbd, RatioObd, NoStep, Planar, Unfitted, MoveBound };

struct PassStop {
  SolvePass pass = SolvePass::Only;
  PatchStop reason = PatchStop::MaxIter;
  double plateau_removed = 0;  // Plateau: percent of G_ABD the last iterations removed
  double stop_abd = 0;         // Plateau: δ_ABD, percent
  int iterations_run = 0;      // accepted iterations, including those after the kept one
  int kept = 0;                // the kept (best) iteration
  int refit_after = -1;        // iterations before the curve was re-fitted (deformer.h); -1: never
  bool refit_behind = false;   // re-fitted by auto's race, where it fell behind (term_race.h)
  int anchors_moved_after = -1;  // iterations before the anchors moved (deformer.h); -1: never
  std::string detail;            // NoStep: the refused candidates; Unfitted: why Step 1 failed
};

struct IterationReport {
  int iteration = 0;        // 1-based
  Figures figures;          // after this iteration
  double ratio_abd = 0;     // Eq. (19), percent, vs the previous iteration
  double ratio_obd = 0;     // Eq. (20), percent
  double step_scale = 1;    // 1 = full step; < 1 = shortened by the never-worse rule
  double weight_scale = 1;  // of the developability weights, < 1 after back-offs (deformer.h)
  std::string note;         // why a step was shortened or rejected, if it was
};

// Why a candidate of Developability::Auto's race never started (term_race.h).
enum class NotRun {
  No,                     // it ran
  LeftLittle,             // the first step before it left less than δ_ABD of the start's G_ABD
  LeftLittleInTwo,        // so did its second, taken alone at the first one's pace
  TargetsRemovedNothing,  // both: the curve targets' first step removed nothing, the rows' some
};

// One candidate of Developability::Auto's race (term_race.h).
struct CandidateReport {
  Term term = Term::None;
  int iterations = 0;            // accepted iterations it ran
  double abd_reduction = 0;      // of its best iterate, percent
  double mean_disp = 0;          // of its best iterate, model units
  bool kept = false;             // the one whose result the patch keeps
  bool dropped = false;          // stopped after the trial, not by its own stop rule
  NotRun not_run = NotRun::No;   // why it never ran (term_race.h), if it did not
  double weight_factor = 1;      // of the defect weight (auto's stronger rows: group_run.h)
  bool moved_further = false;    // the stronger rows: dropped having moved further than the bound
  bool late = false;             // started once the leader had stopped (both, term_race.h)
  bool fell_short = false;       // the stronger rows: dropped short of the bar by their pace, or
                                 // after the rows' plateau by their own first plateau
  Term bounded_by = Term::None;  // the stronger rows after a pick of the rows: whose move bounds
                                 // them (group_run.h); None: the pick's, or none (after_plateau)
  bool after_plateau = false;    // the stronger rows after the rows' plateau: the tolerance alone
                                 // bounds them (group_run.h)
  double outdone_by = 0;         // the stronger rows: the weight factor of rows that left less
                                 // where these passed their bar, or outpaced these (0: neither)
  bool outpaced = false;         // the stronger rows: stopped where their pace would not beat the
                                 // rows kept so far
  bool started() const { return not_run == NotRun::No; }
};

// Where the time went, in milliseconds summed over groups (and threads), and solver counts.
struct StageTimes {
  double setup = 0;          // validation, topology, solve groups, MLS weights, ordering, pattern
  double step1 = 0;          // DEGI, skeleton curve, target normals and their re-projection
  double assembly = 0;       // the matrix M and the right-hand sides
  double factorization = 0;  // symbolic analysis and numeric factorisations
  double solve = 0;          // forward and back substitutions
  double metrics = 0;        // figures for the stop criteria, the never-worse rule, the reports
  int factorizations = 0;
  double factorization_flops = 0;  // of those factorisations (sparse_factor.h)
  double solve_bytes = 0;          // the least the solves read: L per pass, M per CG product
  int solves = 0;                  // linear solves, one per iteration
  int cg_iterations = 0;           // conjugate-gradient iterations of the iterative solves
  int cg_truncated = 0;            // iterative solves CG gave up on (solve_strategy.h)
  int substituted = 0;             // systems factorised by another back end than the one asked for
  StageTimes& operator+=(const StageTimes& o) {
    setup += o.setup, step1 += o.step1, assembly += o.assembly, factorization += o.factorization;
    solve += o.solve, metrics += o.metrics;
    factorizations += o.factorizations, factorization_flops += o.factorization_flops;
    solve_bytes += o.solve_bytes;
    solves += o.solves, cg_iterations += o.cg_iterations, cg_truncated += o.cg_truncated;
    substituted += o.substituted;
    return *this;
  }
};

// Why a patch is solved in a neighbour's solve group (solve_groups.h).
enum class JoinReason {
  MostlySeams,      // fewer interior vertices than seam and boundary ones: always joined
  CurvatureOnSeams  // more |K| on its seam vertices than inside: joined where that is measured
                    // to remove more (JoinTrial)
};

struct PatchJoin {
  int patch = 0;  // a patch id
  int faces = 0;
  int group = 0;  // the patch id of the group it is solved in
  JoinReason reason = JoinReason::MostlySeams;
};

// The mesh solved both with the patches that hold most of their curvature on their seams
// joined to a neighbour and with their seams held (quasidev.cpp), and which was kept.
struct JoinTrial {
  int patches = 0;    // patches joined for their curvature on seams
  double joined = 0;  // G_ABD reduction with them joined, percent
  double held = 0;    // with their seams held, percent
  bool kept_joined = false;
};

struct PatchReport {
  int id = 0;
  int faces = 0;
  int vertices = 0;
  int free_vertices = 0;
  double tolerance = 0;                            // δ_err used, model units
  TargetKind target_kind = TargetKind::Unchanged;  // the Step 1 model
  bool fitted = false;               // Step 1 fitted a model (else the faces keep their normals)
  Term developability = Term::None;  // rows used
  TermChoice developability_reason = TermChoice::AsAsked;  // why (Auto: candidates' figures)
  std::vector<CandidateReport> candidates;  // Developability::Auto's race, else empty
  double fit_residual_deg = 0;              // area-weighted mean angle between n_f and its target
  int iterations = 0;                       // accepted iterations up to the kept (best) iterate
  int iterations_run = 0;       // accepted iterations, including those after the kept one
  std::vector<PassStop> stops;  // one per pass that solved the patch, in order
  Figures before;
  Figures after;
  double abd_reduction = 0;  // (G_before − G_after)/G_before, percent
  double obd_reduction = 0;  // same for D(P), measured with the initial targets
  double time_ms = 0;
  StageTimes times;       // of the solve groups it was in (shared with their other patches)
  int group_patches = 1;  // the most patches one of those groups held
  std::vector<IterationReport> history;
};

struct Result {
  Positions V;                   // new positions, same order as the input
  double average_edge = 0;       // AE of the input
  std::vector<double> k_before;  // K(v) per vertex, 0 on boundary / unused vertices
  std::vector<double> k_after;
  std::vector<double> displacement;  // |v' − v0| per vertex
  std::vector<PatchReport> patches;  // in ascending patch id order
  Figures total_before;              // whole mesh
  Figures total_after;
  double abd_reduction = 0;  // whole mesh, percent
  int factorizations = 0;    // sparse Cholesky numeric factorisations performed
  StageTimes times;          // per stage (with a join trial, of both solves); time_ms is the
                             // wall-clock total
  double time_ms = 0;
  std::vector<int> segmented_patch;     // patch id per face when the engine split the mesh first
                                        // (segment_first.h), else empty
  std::vector<PatchJoin> joins;         // patches solved in a neighbour's group, by patch id
  std::optional<JoinTrial> join_trial;  // when both groupings were solved
  std::vector<std::string> warnings;  // parts of the mesh left as they are (validate.h warnings())
  std::vector<std::string> log;       // human-readable lines: the warnings, one per patch, total
};

}  // namespace qd::approximate
