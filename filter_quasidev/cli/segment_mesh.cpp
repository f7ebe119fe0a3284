#include "segment_mesh.h"

#include "io/ply_mesh.h"
#include "mesh_geometry.h"

namespace qd::cli {

namespace {

// Per triangle, 1 where the face `flags` have the selection bit; empty when none is selected.
std::vector<char> selected_faces(const io::MeshDocument& mesh) {
  for (const io::PlyProperty& p : mesh.face_extra) {
    if (p.name != "flags" || p.is_list) continue;
    std::vector<char> selected(mesh.triangles.size(), 0);
    bool any = false;
    for (std::size_t f = 0; f < selected.size(); ++f)
      any |= (selected[f] = io::has_selected_flag(p.values[f])) != 0;
    if (any) return selected;
  }
  return {};
}

}  // namespace

segment::SegmentProblem make_segment_problem(const io::MeshDocument& mesh,
                                             const SegmentOptions& o) {
  segment::SegmentProblem problem;
  set_geometry(mesh, problem);
  if (!o.settings.keep_patches) problem.patch.clear();
  if (o.settings.selection_border) problem.selected = selected_faces(mesh);
  problem.params = o.settings.engine;
  return problem;
}

}  // namespace qd::cli
