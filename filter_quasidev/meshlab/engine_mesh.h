// What every adapter hands the engine from MeshLab, one source for each MeshLab generation: the
// live (not deleted) vertices and faces of a CMeshO as qd::common::Positions /
// qd::common::Triangles, where each lives in m.vert / m.face (so results are written back in
// place), the patch id per face, and MeshLab's progress callback as the engine's.
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
EngineMesh read_geometry(const CMeshO& m, qd::common::Positions& V, qd::common::Triangles& F);

// Patch id per engine face = the per-face quality rounded to the nearest integer, when the mesh
// has per-face quality and use_patches; else empty (the whole mesh is one patch). Says which in
// `log`. Throws qd::common::Error for a quality that is not a number or too large for a patch id.
std::vector<int> read_patch_ids(const CMeshO& m, const EngineMesh& e, bool has_face_quality,
                                bool use_patches, std::vector<std::string>& log);

// Per engine element, 1 where the element elements[slots[i]] (m.vert or m.face) is selected;
// empty when none is.
template <typename Elements>
std::vector<char> read_selected(const Elements& elements, const std::vector<std::size_t>& slots) {
  std::vector<char> selected(slots.size(), 0);
  bool any = false;
  for (std::size_t i = 0; i < slots.size(); ++i)
    if (elements[slots[i]].IsS()) {
      selected[i] = 1;
      any = true;
    }
  if (!any) selected.clear();
  return selected;
}

// The engine's progress reports passed on to cb (which may be null).
qd::common::Progress progress_of(vcg::CallBackPos* cb);

}  // namespace qdml
