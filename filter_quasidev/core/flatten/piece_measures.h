// How far a flattened piece is from its 3D patch (docs/design.md "Metrics", Flattening), and
// whether it can be cut out as it is.
#pragma once

#include <vector>

#include "flatten/edge_table.h"
#include "flatten/flat_triangles.h"

namespace qd::flatten {

struct PieceMeasures {
  std::vector<double> stretch;  // per face: signed_stretch (face_distortion.h)
  double max_distortion = 0;    // percent: largest length distortion max(σ1 − 1, 1 − σ2)
  double mean_distortion = 0;   // percent: its area-weighted mean
  double area_change = 0;       // percent: (flat area − 3D area) / 3D area, signed areas
  double boundary_change = 0;   // percent: same for the length of the boundary
  int flipped = 0;              // faces with det J ≤ 0
  int overlapping = 0;          // faces with a boundary edge that crosses another one
  bool flattenable() const { return flipped == 0 && overlapping == 0; }
};

// V, F, g, edges: the piece (a disk) in 3D; loops: its boundary loops; uv: its flattening.
PieceMeasures measure_piece(const Positions& V, const Triangles& F, const FlatTriangles& g,
                            const EdgeTable& edges, const std::vector<std::vector<int>>& loops,
                            const Eigen::MatrixX2d& uv);

}  // namespace qd::flatten
