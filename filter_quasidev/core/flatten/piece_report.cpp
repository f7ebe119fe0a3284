#include "flatten/piece_report.h"

#include "common/format_text.h"
#include "flatten/common_names.h"

namespace qd::flatten {

PieceReport piece_report(const FlatPiece& flat, const std::string& label,
                         const Eigen::AlignedBox2d& box) {
  PieceReport r;
  r.patch = flat.piece.patch;
  r.component = flat.piece.component;
  r.label = label;
  r.faces = static_cast<int>(flat.piece.F.rows());
  r.vertices = static_cast<int>(flat.piece.V.rows());
  r.cut = flat.cut.note;
  r.iterations = flat.arap.iterations;
  r.stop_reason = flat.arap.stop_reason;
  r.energy = flat.arap.energy;
  const PieceMeasures& m = flat.measures;
  r.max_distortion = m.max_distortion;
  r.mean_distortion = m.mean_distortion;
  r.area_change = m.area_change;
  r.boundary_change = m.boundary_change;
  r.flipped = m.flipped;
  r.overlapping = m.overlapping;
  r.flattenable = m.flattenable();
  r.box = box;
  r.time_ms = flat.time_ms;
  return r;
}

std::string log_line(const PieceReport& r) {
  std::string s = format_text("patch %s: %d faces", r.label.c_str(), r.faces);
  if (!r.cut.empty()) s += ", " + r.cut;
  s += format_text(
      "; %d ARAP iterations (%s); length distortion max %.2f %%, mean %.2f %%; area %+.2f %%, "
      "boundary %+.2f %%; %d flipped, %d overlapping",
      r.iterations, r.stop_reason.c_str(), r.max_distortion, r.mean_distortion, r.area_change,
      r.boundary_change, r.flipped, r.overlapping);
  if (!r.flattenable) s += ": not flattenable without a cut";
  return s;
}

}  // namespace qd::flatten
