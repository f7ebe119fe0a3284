#include "flatten/flatten_piece.h"

#include <chrono>
#include <string>

#include "common/error.h"
#include "flatten/boundary_loops.h"
#include "flatten/common_names.h"
#include "flatten/cotangent_laplacian.h"
#include "flatten/initial_layout.h"

namespace qd::flatten {

FlatPiece flatten_piece(Piece piece, const FlattenParams& params,
                        const std::function<void(int)>& iteration) {
  const auto t0 = std::chrono::steady_clock::now();
  FlatPiece flat;
  flat.cut = cut_to_disk(piece);
  flat.piece = std::move(piece);
  const Piece& p = flat.piece;
  const int n = static_cast<int>(p.V.rows());
  const EdgeTable edges = edge_table(p.F, n);
  flat.loops = boundary_loops(p.F, edges);
  const FlatTriangles g = flat_triangles(p.V, p.F);
  const Eigen::SparseMatrix<double> L = cotangent_laplacian(p.F, g, n);
  try {
    flat.uv = initial_layout(p.V, p.F, g, L, flat.loops.front(), params.solver);
    flat.arap =
        arap(p.F, g, L, flat.uv,
             ArapSettings{params.max_iterations, params.tolerance, params.solver}, iteration);
  } catch (const Error& e) {
    throw Error("patch " + std::to_string(p.patch) + " cannot be flattened: " + e.what());
  }
  if (!flat.uv.allFinite())
    throw Error("patch " + std::to_string(p.patch) +
                " cannot be flattened: its flattening is not finite "
                "(near-degenerate faces?); remove tiny faces first.");
  flat.measures = measure_piece(p.V, p.F, g, edges, flat.loops, flat.uv);
  flat.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return flat;
}

}  // namespace qd::flatten
