#include "group_mesh.h"

#include <algorithm>
#include <limits>

namespace qd {

double patch_tolerance(const Params& params, int patch_id) {
  const auto it = params.patch_tolerance.find(patch_id);
  return it == params.patch_tolerance.end() ? params.tolerance : it->second;
}

GroupMesh extract_group(const Positions& V, const Triangles& F, const std::vector<int>& faces,
                        const std::vector<int>& face_patch_ids, const std::vector<char>& constrained,
                        const std::vector<char>& interior, const std::vector<int>& face_count,
                        const Params& params) {
  GroupMesh g;
  std::vector<int> local(static_cast<size_t>(V.rows()), -1);
  std::vector<int> faces_in_group;  // per local vertex
  g.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t k = 0; k < faces.size(); ++k) {
    const int f = faces[k];
    const int id = face_patch_ids[static_cast<size_t>(f)];
    const double tol = patch_tolerance(params, id);
    for (int c = 0; c < 3; ++c) {
      const int v = F(f, c);
      int& l = local[static_cast<size_t>(v)];
      if (l < 0) {
        l = static_cast<int>(g.global_vertex.size());
        g.global_vertex.push_back(v);
        g.tolerance.push_back(std::numeric_limits<double>::infinity());
        faces_in_group.push_back(0);
      }
      const auto lu = static_cast<size_t>(l);
      g.tolerance[lu] = std::min(g.tolerance[lu], tol);
      ++faces_in_group[lu];
      g.F(static_cast<Eigen::Index>(k), c) = l;
    }
    g.global_face.push_back(f);
    g.face_patch.push_back(id);
  }
  const size_t n = g.global_vertex.size();
  g.V0.resize(static_cast<Eigen::Index>(n), 3);
  g.fixed.resize(n);
  for (size_t l = 0; l < n; ++l) {
    const auto v = static_cast<size_t>(g.global_vertex[l]);
    g.V0.row(static_cast<Eigen::Index>(l)) = V.row(static_cast<Eigen::Index>(v));
    g.fixed[l] = constrained[v];
    if (interior[v] && faces_in_group[l] == face_count[v]) g.owned.push_back(static_cast<int>(l));
  }
  return g;
}

}  // namespace qd
