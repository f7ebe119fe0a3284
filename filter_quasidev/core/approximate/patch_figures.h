// The figures of the reports (metrics.h: G_ABD, Eq. 18; D(P), Eq. 20; displacements), from the
// angles of every vertex before and after: per patch on its own faces, vertices and interior
// vertices (the curvature of a seam vertex counts in every patch it touches), and for the mesh.
#pragma once

#include <map>
#include <vector>

#include "approximate/result.h"

namespace qd::approximate {

// Fills the reports' sizes and figures and r's per-vertex and total figures. r.V holds the
// result; V0 the input; initial_target: per face; constrained, interior: per vertex.
void measure_result(Result& r, std::map<int, PatchReport>& reports, const Positions& V0,
                    const Triangles& F, const std::vector<int>& patch,
                    const std::vector<Vec3>& initial_target, const std::vector<char>& interior,
                    const std::vector<char>& constrained, size_t threads);

}  // namespace qd::approximate

namespace qd::approximate {

// Percent of the input's G_ABD (k: K per vertex) on interior vertices that no group moves.
double held_curvature_share(const std::vector<double>& k, const std::vector<char>& interior,
                            const std::vector<char>& constrained);

}  // namespace qd::approximate
