// Checks of a Problem before any work (docs/design.md "Bad input"): the mesh checks of
// common/validate_mesh.h and those of the approximation, in one order; each throws
// qd::common::Error with one line saying what is wrong and what to do. All checks are O(n log n).
#include "approximate/validate.h"

#include <cmath>
#include <string>

#include "approximate/common_names.h"
#include "common/error.h"
#include "common/message_text.h"
#include "common/validate_mesh.h"

namespace qd::approximate {

namespace {

void check_sizes(const Problem& p) {
  if (!p.patch.empty() && p.patch.size() != static_cast<size_t>(p.F.rows()))
    throw Error("Got " + std::to_string(p.patch.size()) + " patch ids for " +
                to_text(int(p.F.rows())) +
                " faces: give one patch id per face, or none for a single patch.");
  if (!p.constrained.empty() && p.constrained.size() != static_cast<size_t>(p.V.rows()))
    throw Error("Got " + std::to_string(p.constrained.size()) + " constrained flags for " +
                to_text(int(p.V.rows())) + " vertices: give one flag per vertex, or none.");
}

bool positive(double x) { return std::isfinite(x) && x > 0; }

void check_percent(const char* name, double x) {
  if (!std::isfinite(x) || x < 0 || x >= 100)
    throw Error(std::string("The stop threshold ") + name + " is " + to_text(x) +
                ": it is a percentage, use a value in [0, 100), e.g. 1.");
}

void check_params(const Params& q) {
  if (!positive(q.tolerance))
    throw Error("The deformation tolerance is " + to_text(q.tolerance) +
                ": use a positive distance, e.g. a few tenths of the average edge length.");
  for (const auto& [id, tol] : q.patch_tolerance)
    if (!positive(tol))
      throw Error("The tolerance of patch " + to_text(id) + " is " + to_text(tol) +
                  ": use a positive distance or drop the override.");
  if (q.max_iter < 1 || q.max_iter > 10000)
    throw Error("The maximum number of iterations is " + to_text(q.max_iter) +
                ": use a value from 1 to 10000, e.g. 10.");
  if (!positive(q.weight))
    throw Error("The developability weight w is " + to_text(q.weight) +
                ": use a positive value, e.g. 30.");
  if (!std::isfinite(q.anchor) || q.anchor < 0)
    throw Error("The anchor weight is " + to_text(q.anchor) +
                ": use a value >= 0, e.g. 10 (0 disables the anchor).");
  check_percent("ABD", q.stop_abd);
  check_percent("OBD", q.stop_obd);
}

// Fails only when no patch is large enough; smaller ones are left unchanged (see warnings()).
void check_patch_sizes(const Topology& t) {
  if (t.small_patches == t.patches)
    throw Error("Patch " + to_text(t.first_small_patch[0]) + " has only " +
                count_text(t.first_small_patch[1], "face", "faces") + " (" +
                count_text(t.small_patches, "patch has", "patches have") + " fewer than " +
                to_text(kMinPatchFaces) + "): a patch needs at least " + to_text(kMinPatchFaces) +
                " faces; merge small patches into their neighbours.");
}

// What holds a vertex in place, counted over the used vertices for the message below.
struct ConstraintCounts {
  int used = 0, selected = 0, seams = 0, boundary = 0, nonmanifold = 0, small_patches = 0;
};

void check_free_vertices(const Problem& p, const Topology& t) {
  const bool fix_seams = p.params.seams == SeamMode::Fixed;
  ConstraintCounts n;
  for (size_t v = 0; v < t.used.size(); ++v) {
    if (!t.used[v]) continue;
    ++n.used;
    const bool is_selected = !p.constrained.empty() && p.constrained[v];
    const bool is_seam = fix_seams && t.seam[v];
    const bool is_boundary = p.params.keep_boundary && t.boundary[v];
    if (!is_selected && !is_seam && !is_boundary && !t.nonmanifold[v] && !t.in_small_patch[v])
      return;
    n.selected += is_selected;
    n.seams += is_seam;
    n.boundary += is_boundary;
    n.nonmanifold += t.nonmanifold[v];
    n.small_patches += t.in_small_patch[v];
  }
  // The kept parts are named only when present, so a clean mesh reads as it always has.
  std::string kept;
  if (n.nonmanifold > 0) kept += ", " + to_text(n.nonmanifold) + " on non-manifold edges";
  if (n.small_patches > 0)
    kept += ", " + to_text(n.small_patches) + " in patches of fewer than " +
            to_text(kMinPatchFaces) + " faces";
  throw Error("All " + to_text(n.used) + " vertices are constrained (" + to_text(n.selected) +
              " selected, " + to_text(n.seams) + " on fixed seams, " + to_text(n.boundary) +
              " on the kept boundary" + kept +
              "), so nothing can move: select fewer vertices, free the seams or let the boundary "
              "move" +
              (kept.empty() ? "" : ", or repair the mesh") + ".");
}

}  // namespace

Topology validate(const Problem& problem) {
  check_not_empty(problem.V, problem.F);
  check_sizes(problem);
  check_coordinates(problem.V);  // before the parameters: a NaN mesh makes a NaN tolerance
  check_face_indices(problem.F, static_cast<int>(problem.V.rows()));
  check_zero_area(problem.V, problem.F);
  check_params(problem.params);
  Topology topology =
      analyse_topology(problem.F, static_cast<int>(problem.V.rows()), problem.patch);
  check_duplicate_faces(topology);
  check_patch_sizes(topology);
  check_orientation(topology);
  check_free_vertices(problem, topology);
  return topology;
}

std::vector<std::string> warnings(const Topology& t) {
  std::vector<std::string> out = mesh_warnings(t);
  if (t.small_patches > 0)
    out.push_back(count_text(t.small_patches, "patch has", "patches have") + " fewer than " +
                  to_text(kMinPatchFaces) + " faces (first: patch " +
                  to_text(t.first_small_patch[0]) + ", " +
                  count_text(t.first_small_patch[1], "face", "faces") +
                  "): left unchanged; to process them, merge them into their neighbours.");
  return out;
}

}  // namespace qd::approximate
