// Step 1 and Step 2 of one solve group (Algorithm 1 of the paper on its patches): the per-patch
// fit and choice of term (patch_fit.h; Developability::Auto races the candidates, term_race.h),
// then the deformation from the positions the earlier groups left.
#pragma once

#include <functional>
#include <map>
#include <vector>

#include "approximate/common_names.h"
#include "approximate/deformer.h"
#include "approximate/group_mesh.h"
#include "approximate/params.h"
#include "approximate/patch_fit.h"
#include "approximate/term_race.h"
#include "common/idle_threads.h"
#include "common/topology.h"

namespace qd::approximate {

// What every group of a solve shares.
struct SolveInput {
  const Positions& input;  // the positions before any group moved them
  const Triangles& F;
  const std::vector<int>& patch;      // patch id per face
  const std::vector<char>& interior;  // per vertex
  const VertexFaces& incident;
  const Params& params;
  double ae = 0;  // the input's average edge length
};

struct GroupRun {
  GroupMesh group;
  std::vector<PatchFit> fits;
  std::vector<Vec3> targets;  // initial target per group face
  DeformOutcome outcome;
  std::vector<CandidateFigures> race;  // Developability::Auto's candidates, if it raced
  double initial_g = 0;                // the group's G_ABD when it started
  double time_ms = 0;
};

// Developability::Auto, where the race picked curve targets (curve or both) for a patch of the
// group and left more than δ_ABD of the start's G_ABD (less, and nothing could remove a meaningful
// share more): the angle-defect rows alone at each of the stronger weights below run from the
// start, and the group keeps the best of them only where it dominates the pick: less G_ABD left,
// and the vertices moved no further, on average or at most. No trade-off is made for the user
// (--defect-weight moves along the curve); the run stops as soon as an iterate has moved further
// than the pick's result, or, as a candidate of the race does, once kNothingRounds iterations
// removed nothing, and is judged by its best iterate within that move (the irregular lampshade with
// bumps of 0.3 AE of seed 3: both's 62 % against the rows' 76 % within its move and 92 % a step
// beyond it). Where triangles do not follow the rulings (an irregular triangulation of a smooth
// cylinder, cone or lampshade) no face normal can reach the curve targets, while the rows, which
// only ask each vertex's angles to sum to 2π, can: on such members of scripts/mesh_family.py
// (`irregular`) the pick removed 52–99 % where these rows remove 85–100 % and move less. Where the
// pick is the rows at the given weight, a stronger pull removes more by moving further (the
// anchors' share of the least-squares energy grows with the weight), which is the user's
// trade-off to make, with two exceptions. Where the pick ran to maxIter and a raced candidate with
// curve targets moved further on average, auto would have accepted that move had it won. There the
// stronger rows run too, bounded by that candidate's move (the one that moved most, on average
// and at most) instead of the pick's, and are kept only where they leave at most
// kStrongerRowsLeave of the pick's G_ABD; they also stop once the pace of their iterations so
// far (up to the last kPlateauIterations) would not take them there by maxIter (projected_g_abd,
// term_race.h). And where the pick stopped at its plateau before maxIter (its own stop rule:
// more iterations at that weight remove no meaningful share), a stronger pull is the only way on,
// and no candidate's move is a fit bound for it (on the irregular tangent developables of the
// sweep the curve steps remove nothing and move least, and the stronger rows start slowly): there
// they run, without the pace test, until a vertex has moved further from the start than the
// tolerance lets it move in one iteration or their own first plateau finds them short, and are
// kept only where they leave at most kStrongerRowsLeave of the pick's G_ABD. (Bounded by the
// tolerance of each iteration alone, they took a smooth torus from 0.6 % to 95 % by moving it 7.4
// AE, a trade only the user can make.) Not above kMaxDefectRaceVertices, where the rows are not
// raced for their cost. Measurements behind the weights and the share: docs/robustness.md.
//
// The stronger rows' weights, as factors of the defect weight: each runs from the start against
// the same bar, and the one that passes it and leaves least G_ABD is kept. A stronger pull
// removes more per iteration but reaches the move bound sooner; which of them goes furthest
// within the bound differs from mesh to mesh, so auto measures them all (stop 62: of the 86
// members of four sweeps where ×30 or ×10 alone did better than ×100 alone, 38 did best at ×30
// and 48 at ×10; ×3 and ×300 made no further member pass: docs/robustness.md).
constexpr double kStrongerRowsFactors[] = {100, 30, 10};
// Where the rows at the given weight creep (the smooth tangent developables of
// scripts/mesh_family.py, whose rows stop with up to 64 % of G_ABD left), the stronger rows
// bounded by a curve candidate's move left 0.2–24 % of what the pick left on the 11 grid members
// where they did most; where they trade distance for curvature (the shirt's panel of 956 faces:
// 32 → 22 % of its G_ABD, its default then beyond MeshLab's farthest point) 69 %, and 73–100 %
// on three grid members where they gained 0–3 points. So they must remove at least half.
constexpr double kStrongerRowsLeave = 0.5;
// Moves closer than this share are the same move (rounding; group_run.cpp's moved_further).
constexpr double kMoveRounding = 1e-9;

// The terms decided for each patch id by an earlier pass's race (Developability::Auto).
using DecidedTerms = std::map<int, Term>;

// Runs the group of `faces` from positions V; `constrained`: per vertex, held by the pass;
// one_unit: the group's patches share one step scale (solved as one patch). `params.threads`
// is the group's share of the threads; idle: its round's idle threads, which a race borrows.
GroupRun run_group(const SolveInput& in, const Positions& V, const std::vector<int>& faces,
                   const std::vector<char>& constrained, const Params& params,
                   const DecidedTerms& decided, bool one_unit, common::IdleThreads& idle,
                   const std::function<void(double)>& progress);

}  // namespace qd::approximate
