// Checks of a triangle mesh shared by every job (docs/design.md "Bad input"). Each check_* throws
// qd::common::Error with one line saying what is wrong and what to do; mesh_warnings() names the
// parts of a workable mesh that a job keeps as they are. A job calls the checks in this order,
// interleaved with its own (approximate/validate.h).
#pragma once

#include <string>
#include <vector>

#include "common/mesh.h"
#include "common/topology.h"

namespace qd::common {

// Zero-area threshold: a face is degenerate when its area < kZeroAreaRatio · AE².
constexpr double kZeroAreaRatio = 1e-12;

// No vertices, or no faces.
void check_not_empty(const Positions& V, const Triangles& F);
// NaN or infinite coordinates.
void check_coordinates(const Positions& V);
// Face indices outside [0, vertex_count), or a vertex used twice by one face.
void check_face_indices(const Triangles& F, int vertex_count);
// Faces of area below kZeroAreaRatio · AE² (all of them when AE is 0).
void check_zero_area(const Positions& V, const Triangles& F);
// Faces with the same three vertices (t from analyse_topology).
void check_duplicate_faces(const Topology& t);
// Two faces of one patch running the same way along an edge.
void check_orientation(const Topology& t);

// Non-manifold edges: their vertices stay fixed and out of the curvature figures.
std::vector<std::string> mesh_warnings(const Topology& t);

}  // namespace qd::common
