#include "flatten_figures.h"

namespace qdml {

std::map<std::string, Figure> flatten_figures(const qd::flatten::FlattenResult& r) {
  using P = qd::flatten::PieceReport;
  const Eigen::AlignedBox2d& sheet = r.pattern.bounds;
  return {
      {"pieces", static_cast<int>(r.pieces.size())},
      {"flattenable_pieces", r.flattenable_pieces},
      {"max_distortion", r.max_distortion},
      {"sheet_width", sheet.isEmpty() ? 0.0 : sheet.sizes().x()},
      {"sheet_height", sheet.isEmpty() ? 0.0 : sheet.sizes().y()},
      {"time_ms", r.time_ms},
      {"piece_patch", figure_list(r.pieces, [](const P& p) { return p.patch; })},
      {"piece_component", figure_list(r.pieces, [](const P& p) { return p.component; })},
      {"piece_faces", figure_list(r.pieces, [](const P& p) { return p.faces; })},
      {"piece_vertices", figure_list(r.pieces, [](const P& p) { return p.vertices; })},
      {"piece_cut", figure_list(r.pieces, [](const P& p) { return !p.cut.empty(); })},
      {"piece_iterations", figure_list(r.pieces, [](const P& p) { return p.iterations; })},
      {"piece_energy", figure_list(r.pieces, [](const P& p) { return p.energy; })},
      {"piece_max_distortion", figure_list(r.pieces, [](const P& p) { return p.max_distortion; })},
      {"piece_mean_distortion",
       figure_list(r.pieces, [](const P& p) { return p.mean_distortion; })},
      {"piece_area_change", figure_list(r.pieces, [](const P& p) { return p.area_change; })},
      {"piece_boundary_change",
       figure_list(r.pieces, [](const P& p) { return p.boundary_change; })},
      {"piece_flipped", figure_list(r.pieces, [](const P& p) { return p.flipped; })},
      {"piece_overlapping", figure_list(r.pieces, [](const P& p) { return p.overlapping; })},
      {"piece_flattenable", figure_list(r.pieces, [](const P& p) { return p.flattenable; })},
      {"piece_time_ms", figure_list(r.pieces, [](const P& p) { return p.time_ms; })},
  };
}

}  // namespace qdml
