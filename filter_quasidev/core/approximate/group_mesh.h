// A solve group: the faces of one patch (its seams fixed or free) or of all patches (free
// seams' first pass, quasidev.cpp), as a small local mesh with its own vertex numbering, so every
// step costs O(group size). Its faces are followed by a "ring": the other faces that touch the
// group's vertices. The ring is measured (so the curvature of seam vertices counts) but never
// solved or moved.
#pragma once

#include <vector>

#include "approximate/common_names.h"
#include "approximate/params.h"
#include "approximate/problem.h"
#include "common/mesh.h"
#include "common/topology.h"

namespace qd::approximate {

// Faces incident to each vertex, in compressed rows: faces[start[v] .. start[v+1]).
struct VertexFaces {
  std::vector<int> start;
  std::vector<int> faces;
  VertexFaces(const Triangles& F, Eigen::Index vertex_count);
};

struct GroupMesh {
  Positions V0;       // positions when the group starts, local numbering
  Positions V_input;  // the engine's input positions, local numbering: a face
                      // whose normal turns against its input one is folded
  Triangles F;        // group faces (rows < solve_faces), then the ring faces
  Eigen::Index solve_faces = 0;
  Eigen::Index solve_vertices = 0;  // local vertices [0, solve_vertices) touch group faces
  std::vector<int> global_vertex;   // local vertex -> input vertex
  std::vector<int> global_face;     // local face -> input face
  std::vector<int> face_patch;      // patch id of each local face
  std::vector<int> face_unit;       // per local face: whose area A_P scales its angle-defect rows
                                    // (angle_defect.h): its patch, or its solve group
                                    // (solve_groups.h) in the per-patch passes
  std::vector<char> fixed;          // constrained, or only in the ring: not an unknown
  std::vector<double> tolerance;    // δ_err of each local vertex (min over its group patches)
  std::vector<int> owned;           // interior vertices of the group faces: their K counts
};

// What each input vertex is: interior (not on an open boundary nor a non-manifold edge, its
// curvature counts) and constrained (selected, on the kept boundary, on a fixed seam, on a
// non-manifold edge or in a patch too small to fit: it never moves).
struct VertexRoles {
  std::vector<char> interior;
  std::vector<char> constrained;
};
VertexRoles vertex_roles(const Problem& problem, const Topology& topo, SeamMode seams);

// δ_err of a patch: its own tolerance if given, else the global one.
double patch_tolerance(const Params& params, int patch_id);

// Builds the local mesh of a group from the current positions V. faces: input faces of the
// group; face_patch_ids: patch id per input face; constrained and interior (not on an open
// boundary): per input vertex; incident: faces of each input vertex.
GroupMesh extract_group(const Positions& V, const Triangles& F, const std::vector<int>& faces,
                        const std::vector<int>& face_patch_ids,
                        const std::vector<char>& constrained, const std::vector<char>& interior,
                        const VertexFaces& incident, const Params& params);

}  // namespace qd::approximate
