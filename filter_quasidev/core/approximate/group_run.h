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
