// Checks a Problem before any work: throws qd::Error with a message that says what was wrong
// and what to do (DESIGN.md "Bad input"). Accepts odd but workable input: silently, or with a
// warning where part of the mesh is left as it is.
#pragma once

#include <string>
#include <vector>

#include "problem.h"
#include "topology.h"

namespace qd {

// Zero-area threshold: a face is degenerate when its area < kZeroAreaRatio · AE².
constexpr double kZeroAreaRatio = 1e-12;

// The mesh checks shared by every job, in the order a job calls them: no vertices or no faces;
// NaN or infinite coordinates; face indices outside [0, vertex_count) or a vertex used twice by
// one face; faces of area below kZeroAreaRatio · AE²; faces with the same three vertices
// (t from analyse_topology).
void check_not_empty(const Positions& V, const Triangles& F);
void check_coordinates(const Positions& V);
void check_face_indices(const Triangles& F, int vertex_count);
void check_zero_area(const Positions& V, const Triangles& F);
void check_duplicate_faces(const Topology& t);

// Returns the topology it computed, so callers need not compute it again. Fails only when
// nothing can be processed: non-manifold edges and patches too small to fit are kept as they
// are (see warnings()).
Topology validate(const Problem& problem);

// One line per part of the mesh the run keeps as it is (vertices on non-manifold edges,
// patches of fewer than kMinPatchFaces faces), with a count, the first example and what to do.
std::vector<std::string> warnings(const Topology& topology);

}  // namespace qd
