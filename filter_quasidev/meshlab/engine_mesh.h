// What every adapter hands the engine from MeshLab, one source for each MeshLab generation: the
// live (not deleted) vertices and faces of a CMeshO as qd::Positions / qd::Triangles, where each
// lives in m.vert / m.face (so results are written back in place), the patch id per face, and
// MeshLab's progress callback as the engine's.
#pragma once

#include <string>
#include <vector>

#if __has_include(<common/ml_document/cmesh.h>)
#include <common/ml_document/cmesh.h>  // MeshLab 2025.07
#else
#include <common/ml_mesh_type.h>  // MeshLab 2020.09
#endif

#include "common/mesh.h"
#include "common/progress.h"

namespace qdml {

struct EngineMesh {
  std::vector<std::size_t> vertex_slot;  // engine vertex i -> index into m.vert
  std::vector<std::size_t> face_slot;    // engine face f -> index into m.face
};

// The one CMeshO -> engine copy: the live vertices and faces straight into V and F.
EngineMesh read_geometry(const CMeshO& m, qd::Positions& V, qd::Triangles& F);

// Patch id per engine face = the per-face quality rounded to the nearest integer, when the mesh
// has per-face quality and use_patches; else empty (the whole mesh is one patch). Says which in
// `log`. Throws qd::Error for a quality that is not a number or too large for a patch id.
std::vector<int> read_patch_ids(const CMeshO& m, const EngineMesh& e, bool has_face_quality,
                                bool use_patches, std::vector<std::string>& log);

// The engine's progress reports passed on to cb (which may be null).
qd::Progress progress_of(vcg::CallBackPos* cb);

}  // namespace qdml
