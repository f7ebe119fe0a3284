// The second developability term (issue 11; beyond the paper): Gauss–Newton rows on the
// interior angle defects, for patches whose Gauss image is a 2-D blob (draped, wrinkled
// panels), where the paper's one-curve targets of Step 1 are wrong.
//
// A vertex v is developable when its angle defect K_v = 2π − Σ_f θ_v^f vanishes (the corner
// angles θ_v^f of its faces f then unfold flat). Linearised at the current positions x:
//   s_v · (K_v + Σ_u ∇_u K_v · (x'_u − x_u)) = 0          for every row vertex v,
// summed over the star of v (v and its neighbours u). For a corner angle θ at vertex i of a
// face (i, j, k), with e_j = x_j − x_i, e_k = x_k − x_i and n the unit face normal:
//   ∂θ/∂x_j = −(n × e_j)/|e_j|²,  ∂θ/∂x_k = (n × e_k)/|e_k|²,  ∂θ/∂x_i = −∂θ/∂x_j − ∂θ/∂x_k
// (moving x_j towards e_k in the face plane closes the angle; out of the plane it does not
// change to first order), and ∇_u K_v = −Σ_f ∂θ_v^f/∂x_u.
//
// The rows join the shape rows and soft anchors of Eq. (13)/(15) in the same least-squares
// system (deformation_system.h): M gains s_v²·∇K_v∇K_vᵀ, coupling every pair of vertices of a
// star. Their weight is scale- and density-invariant: s_v = w_d · A_P / √A_v, with A_v the
// mixed Voronoi area of v and A_P the area of its patch, so Σ_v (s_v K_v)² ≈ w_d²·A_P²·∫K² dA,
// which scales like the shape rows' Σ|Δe|² (length²) and does not depend on the mesh density.
#pragma once

#include <vector>

#include "approximate/common_names.h"
#include "approximate/group_mesh.h"
#include "common/mesh.h"
#include "common/metrics.h"

namespace qd::approximate {

// The rows of a group, fixed while it is solved: row r linearises the angle defect of local
// vertex vertex[r]; its star (that vertex first, then its neighbours) is
// star[start[r] .. start[r+1]), and its weight is s_r = w_d · patch_area[r] / root_area[r].
struct DefectStars {
  std::vector<int> vertex;
  std::vector<int> start{0};
  std::vector<int> star;
  std::vector<double> patch_area;  // A_P
  std::vector<double> root_area;   // √A_v
  std::vector<double> weight;      // s_r
  // Sets s_r for this w_d (each system weighs the rows it shares for its own, group_run.h).
  void weigh(double w_d);
  bool empty() const { return vertex.empty(); }
};

// Rows for the local vertices with has_row[v] set (free interior vertices of defect patches),
// weighted by w_d = weight (A_P of a seam vertex: the mean over its faces of their patch's area).
// A vertex whose mixed area vanishes gets no row.
DefectStars defect_stars(const GroupMesh& g, const VertexFaces& incident,
                         const std::vector<char>& has_row, double weight);

// K_v and ∇K_v of every row at positions X: defect[r], and gradient[i] = ∂K_v/∂x_u for the
// star entry i (same indexing as DefectStars::star). K_v is taken from `angles`, the
// vertex_angles of X: the very defects the never-worse rule measures.
struct DefectLinearisation {
  std::vector<double> defect;
  std::vector<Vec3> gradient;
};
DefectLinearisation linearise_defects(const DefectStars& rows, const GroupMesh& g,
                                      const VertexFaces& incident, const Positions& X,
                                      const VertexAngles& angles);

}  // namespace qd::approximate
