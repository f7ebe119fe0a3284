// Checks of a Problem before any work (DESIGN.md "Bad input"): each check throws qd::Error
// with one line saying what is wrong and what to do. All checks are O(n log n).
#include "validate.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "error.h"

namespace qd {

namespace {

std::string str(int n) { return std::to_string(n); }

// "1 face", "3 faces".
std::string count(int n, const char* one, const char* many) {
  return str(n) + " " + (n == 1 ? one : many);
}

std::string str(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

void check_sizes(const Problem& p) {
  if (!p.patch.empty() && p.patch.size() != static_cast<size_t>(p.F.rows()))
    throw Error("Got " + std::to_string(p.patch.size()) + " patch ids for " + str(int(p.F.rows())) +
                " faces: give one patch id per face, or none for a single patch.");
  if (!p.constrained.empty() && p.constrained.size() != static_cast<size_t>(p.V.rows()))
    throw Error("Got " + std::to_string(p.constrained.size()) + " constrained flags for " +
                str(int(p.V.rows())) + " vertices: give one flag per vertex, or none.");
}

bool positive(double x) { return std::isfinite(x) && x > 0; }

void check_percent(const char* name, double x) {
  if (!std::isfinite(x) || x < 0 || x >= 100)
    throw Error(std::string("The stop threshold ") + name + " is " + str(x) +
                ": it is a percentage, use a value in [0, 100), e.g. 1.");
}

void check_params(const Params& q) {
  if (!positive(q.tolerance))
    throw Error("The deformation tolerance is " + str(q.tolerance) +
                ": use a positive distance, e.g. a few tenths of the average edge length.");
  for (const auto& [id, tol] : q.patch_tolerance)
    if (!positive(tol))
      throw Error("The tolerance of patch " + str(id) + " is " + str(tol) +
                  ": use a positive distance or drop the override.");
  if (q.max_iter < 1 || q.max_iter > 10000)
    throw Error("The maximum number of iterations is " + str(q.max_iter) +
                ": use a value from 1 to 10000, e.g. 10.");
  if (!positive(q.weight))
    throw Error("The developability weight w is " + str(q.weight) +
                ": use a positive value, e.g. 30.");
  if (!std::isfinite(q.anchor) || q.anchor < 0)
    throw Error("The anchor weight is " + str(q.anchor) +
                ": use a value >= 0, e.g. 10 (0 disables the anchor).");
  check_percent("ABD", q.stop_abd);
  check_percent("OBD", q.stop_obd);
}

// Fails only when no patch is large enough; smaller ones are left unchanged (see warnings()).
void check_patch_sizes(const Topology& t) {
  if (t.small_patches == t.patches)
    throw Error("Patch " + str(t.first_small_patch[0]) + " has only " +
                count(t.first_small_patch[1], "face", "faces") + " (" +
                count(t.small_patches, "patch has", "patches have") + " fewer than " +
                str(kMinPatchFaces) + "): a patch needs at least " + str(kMinPatchFaces) +
                " faces; merge small patches into their neighbours.");
}

void check_orientation(const Topology& t) {
  if (t.misoriented_edges > 0)
    throw Error("Patch " + str(t.first_misoriented_patch) + " is not consistently oriented (faces " +
                str(t.first_misoriented_faces[0]) + " and " + str(t.first_misoriented_faces[1]) +
                " run along edge " + str(t.first_misoriented_edge[0]) + "-" +
                str(t.first_misoriented_edge[1]) + " the same way; " +
                count(t.misoriented_edges, "such edge", "such edges") +
                "): fix it first (MeshLab: Filters > Normals, Curvatures and Orientation > "
                "Re-Orient all faces coherently).");
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
  if (n.nonmanifold > 0) kept += ", " + str(n.nonmanifold) + " on non-manifold edges";
  if (n.small_patches > 0)
    kept += ", " + str(n.small_patches) + " in patches of fewer than " + str(kMinPatchFaces) + " faces";
  throw Error("All " + str(n.used) + " vertices are constrained (" + str(n.selected) +
              " selected, " + str(n.seams) + " on fixed seams, " + str(n.boundary) +
              " on the kept boundary" + kept +
              "), so nothing can move: select fewer vertices, free the seams or let the boundary "
              "move" + (kept.empty() ? "" : ", or repair the mesh") + ".");
}

int count_flags(const std::vector<char>& flags) {
  return static_cast<int>(std::count(flags.begin(), flags.end(), 1));
}

}  // namespace

void check_not_empty(const Positions& V, const Triangles& F) {
  if (V.rows() == 0) throw Error("The mesh has no vertices: load a triangle mesh first.");
  if (F.rows() == 0)
    throw Error("The mesh has no faces (a point cloud?): the filter needs a triangle mesh; "
                "reconstruct a surface first.");
}

void check_coordinates(const Positions& V) {
  int bad = 0;
  int first = -1;
  for (int v = 0; v < V.rows(); ++v) {
    if (V.row(v).allFinite()) continue;
    if (bad++ == 0) first = v;
  }
  if (bad > 0)
    throw Error("The mesh has " + count(bad, "vertex", "vertices") +
                " with NaN or infinite coordinates (first: vertex " + str(first) + "): remove or repair them before running the filter.");
}

void check_face_indices(const Triangles& F, int vertex_count) {
  for (int f = 0; f < F.rows(); ++f) {
    const int a = F(f, 0), b = F(f, 1), c = F(f, 2);
    for (const int v : {a, b, c})
      if (v < 0 || v >= vertex_count)
        throw Error("Face " + str(f) + " refers to vertex " + str(v) + " but the mesh has only " +
                    str(vertex_count) + " vertices: the file is corrupt; re-export the mesh.");
    if (a == b || b == c || c == a)
      throw Error("Face " + str(f) + " uses vertex " + str(a == b || a == c ? a : b) +
                  " twice: remove degenerate faces first (MeshLab: Filters > Cleaning and "
                  "Repairing > Remove Zero Area Faces).");
  }
}

void check_zero_area(const Positions& V, const Triangles& F) {
  const double ae = average_edge_length(V, F);
  const double threshold = kZeroAreaRatio * ae * ae;
  int bad = 0;
  int first = -1;
  for (int f = 0; f < F.rows(); ++f) {
    if (face_area(V, F, f) >= threshold && threshold > 0) continue;
    if (bad++ == 0) first = f;
  }
  if (bad > 0)
    throw Error("The mesh has " + count(bad, "zero-area face", "zero-area faces") + " (first: face " + str(first) +
                "): remove them first (MeshLab: Filters > Cleaning and Repairing > Remove Zero "
                "Area Faces).");
}

// Duplicate faces also make their edges look misoriented: say what is really wrong first.
void check_duplicate_faces(const Topology& t) {
  if (t.duplicate_faces > 0)
    throw Error("The mesh has " + count(t.duplicate_faces, "duplicate face", "duplicate faces") +
                " (first: faces " + str(t.first_duplicate_faces[0]) + " and " +
                str(t.first_duplicate_faces[1]) +
                " use the same vertices): remove them first (MeshLab: Filters > Cleaning and "
                "Repairing > Remove Duplicate Faces).");
}

Topology validate(const Problem& problem) {
  check_not_empty(problem.V, problem.F);
  check_sizes(problem);
  check_coordinates(problem.V);  // before the parameters: a NaN mesh makes a NaN tolerance
  check_face_indices(problem.F, static_cast<int>(problem.V.rows()));
  check_zero_area(problem.V, problem.F);
  check_params(problem.params);
  Topology topology = analyse_topology(problem.F, static_cast<int>(problem.V.rows()), problem.patch);
  check_duplicate_faces(topology);
  check_patch_sizes(topology);
  check_orientation(topology);
  check_free_vertices(problem, topology);
  return topology;
}

std::vector<std::string> warnings(const Topology& t) {
  std::vector<std::string> out;
  if (t.nonmanifold_edges > 0)
    out.push_back(count(t.nonmanifold_edges, "non-manifold edge", "non-manifold edges") +
                  " (more than two faces; first: between vertices " +
                  str(t.first_nonmanifold_edge[0]) + " and " + str(t.first_nonmanifold_edge[1]) +
                  "): their " + count(count_flags(t.nonmanifold), "vertex is", "vertices are") +
                  " kept fixed and left out of the curvature figures; to process them, repair "
                  "the edges (MeshLab: Filters > Cleaning and Repairing > Repair non Manifold "
                  "Edges).");
  if (t.small_patches > 0)
    out.push_back(count(t.small_patches, "patch has", "patches have") + " fewer than " +
                  str(kMinPatchFaces) + " faces (first: patch " + str(t.first_small_patch[0]) +
                  ", " + count(t.first_small_patch[1], "face", "faces") +
                  "): left unchanged; to process them, merge them into their neighbours.");
  return out;
}

}  // namespace qd
