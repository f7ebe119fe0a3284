// A solve group: the faces of one patch (fixed seams) or of all patches (free seams), as a
// small local mesh with its own vertex numbering, so every step costs O(group size).
#pragma once

#include <vector>

#include "mesh.h"
#include "params.h"

namespace qd {

struct GroupMesh {
  Positions V0;                     // original positions, local numbering
  Triangles F;                      // faces, local vertex indices
  std::vector<int> global_vertex;   // local vertex -> input vertex
  std::vector<int> global_face;     // local face -> input face
  std::vector<int> face_patch;      // patch id of each local face
  std::vector<char> fixed;          // local vertex is constrained (eliminated exactly)
  std::vector<double> tolerance;    // δ_err of each local vertex (min over its patches)
  std::vector<int> owned;           // local vertices whose K counts for this group: interior
                                    // vertices of the input all of whose faces are in the group
};

// δ_err of a patch: its own tolerance if given, else the global one.
double patch_tolerance(const Params& params, int patch_id);

// Builds the local mesh of a group. faces: input faces of the group; face_patch_ids: patch id per
// input face; constrained, interior (not on an open boundary) and face_count (faces incident to
// the vertex in the whole mesh): per input vertex.
GroupMesh extract_group(const Positions& V, const Triangles& F, const std::vector<int>& faces,
                        const std::vector<int>& face_patch_ids, const std::vector<char>& constrained,
                        const std::vector<char>& interior, const std::vector<int>& face_count,
                        const Params& params);

}  // namespace qd
