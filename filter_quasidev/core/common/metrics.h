// The figures of docs/design.md "Metrics": OBD (Defs. 2–3), discrete Gaussian curvature with the
// mixed Voronoi area (Eq. 18, Meyer et al. 2003), G_ABD, angle defect, shape difference
// (Defs. 4–5), displacement.
#pragma once

#include <vector>

#include "common/mesh.h"

namespace qd::common {

// Figures of one set of faces/vertices at one moment (docs/design.md "Metrics").
struct Figures {
  double g_abd = 0;         // Σ|K(v)| over owned interior vertices (Eq. 18)
  double angle_defect = 0;  // Σ|2π − Σθ| over the same vertices (density independent)
  double max_abs_k = 0;     // max |K(v)|
  double obd = 0;           // D(P) = Σ d(t) w.r.t. the current targets (Defs. 2–3)
  double shape = 0;         // S(P) w.r.t. the original positions (Defs. 4–5)
  double max_disp = 0;      // max |v' − v0|, model units
  double mean_disp = 0;     // mean |v' − v0| over the group's vertices
};

// Per vertex: the angle defect 2π − Σθ_j (only meaningful for interior vertices) and the mixed
// Voronoi area A_v (Meyer et al. 2003) summed over all incident faces; one pass over the faces.
struct VertexAngles {
  std::vector<double> defect;
  std::vector<double> area;
};
VertexAngles vertex_angles(const Positions& V, const Triangles& F);

// K(v) = (2π − Σθ_j)/A_v (Eq. 18) where interior[v], else 0.
std::vector<double> gaussian_curvature(const VertexAngles& angles,
                                       const std::vector<char>& interior);

// d(t) = Σ|n_t·e_i| (Def. 2, Eq. 1–2) summed over faces (Def. 3, Eq. 3); targets[i] belongs
// to faces[i].
double orientation_developability(const Positions& V, const Triangles& F,
                                  const std::vector<int>& faces, const std::vector<Vec3>& targets);

// S(P) = Σ_t s1 + s2 + s3 (Defs. 4–5, Eqs. 4–7) between original V0 and deformed V.
double shape_difference(const Positions& V0, const Positions& V, const Triangles& F,
                        const std::vector<int>& faces);

// All Figures of a vertex/face set, from angles = vertex_angles(V, F): curvature figures over
// `vertices` (which must be interior), OBD over faces/targets (skipped when targets is empty),
// shape and displacement against V0 over `faces` / `moved` (the vertices whose displacement
// counts).
Figures measure(const VertexAngles& angles, const Positions& V0, const Positions& V,
                const Triangles& F, const std::vector<int>& vertices, const std::vector<int>& faces,
                const std::vector<Vec3>& targets, const std::vector<int>& moved);

}  // namespace qd::common
