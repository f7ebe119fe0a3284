#include "flatten_figures.h"

namespace qdml {

namespace {

template <typename Field>
Figure piece_list(const std::vector<qd::PieceReport>& pieces, Field field) {
  std::vector<double> v;
  v.reserve(pieces.size());
  for (const qd::PieceReport& p : pieces) v.push_back(static_cast<double>(field(p)));
  return v;
}

}  // namespace

std::map<std::string, Figure> flatten_figures(const qd::FlattenResult& r) {
  using P = qd::PieceReport;
  const Eigen::AlignedBox2d& sheet = r.pattern.bounds;
  return {
      {"pieces", static_cast<int>(r.pieces.size())},
      {"flattenable_pieces", r.flattenable_pieces},
      {"max_distortion", r.max_distortion},
      {"sheet_width", sheet.isEmpty() ? 0.0 : sheet.sizes().x()},
      {"sheet_height", sheet.isEmpty() ? 0.0 : sheet.sizes().y()},
      {"time_ms", r.time_ms},
      {"piece_patch", piece_list(r.pieces, [](const P& p) { return p.patch; })},
      {"piece_component", piece_list(r.pieces, [](const P& p) { return p.component; })},
      {"piece_faces", piece_list(r.pieces, [](const P& p) { return p.faces; })},
      {"piece_vertices", piece_list(r.pieces, [](const P& p) { return p.vertices; })},
      {"piece_cut", piece_list(r.pieces, [](const P& p) { return !p.cut.empty(); })},
      {"piece_iterations", piece_list(r.pieces, [](const P& p) { return p.iterations; })},
      {"piece_energy", piece_list(r.pieces, [](const P& p) { return p.energy; })},
      {"piece_max_distortion", piece_list(r.pieces, [](const P& p) { return p.max_distortion; })},
      {"piece_mean_distortion", piece_list(r.pieces, [](const P& p) { return p.mean_distortion; })},
      {"piece_area_change", piece_list(r.pieces, [](const P& p) { return p.area_change; })},
      {"piece_boundary_change", piece_list(r.pieces, [](const P& p) { return p.boundary_change; })},
      {"piece_flipped", piece_list(r.pieces, [](const P& p) { return p.flipped; })},
      {"piece_overlapping", piece_list(r.pieces, [](const P& p) { return p.overlapping; })},
      {"piece_flattenable", piece_list(r.pieces, [](const P& p) { return p.flattenable; })},
      {"piece_time_ms", piece_list(r.pieces, [](const P& p) { return p.time_ms; })},
  };
}

}  // namespace qdml
