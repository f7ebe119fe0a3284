#include "flatten/flatten.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

#include "common/format_text.h"
#include "common/parallel_for.h"
#include "common/serial_libraries.h"
#include "common/thread_count.h"
#include "flatten/common_names.h"
#include "flatten/flatten_piece.h"
#include "flatten/flatten_validate.h"
#include "flatten/grainline.h"
#include "flatten/layout.h"
#include "flatten/notches.h"
#include "flatten/pattern_sheet.h"
#include "flatten/piece_report.h"
#include "flatten/seam_allowance.h"

namespace qd::flatten {

namespace {

constexpr double kAutoNotchSpacing = 0.125;  // of the largest piece's longer side

std::string label_of(const Piece& p) {
  return std::to_string(p.patch) + (p.components > 1 ? "." + std::to_string(p.component) : "");
}

// Notch flags per mesh vertex for the pieces' boundaries (notches.h); spacing 0 = automatic.
std::vector<char> notches_of(const Positions& V, const std::vector<FlatPiece>& flat,
                             const std::vector<Eigen::AlignedBox2d>& boxes, double spacing) {
  std::vector<std::array<int, 2>> boundary_edges;  // in mesh vertices
  double longest = 0;
  for (size_t i = 0; i < flat.size(); ++i) {
    const std::vector<int>& vertex = flat[i].piece.vertex;
    for (const std::vector<int>& loop : flat[i].loops)
      for (size_t k = 0; k < loop.size(); ++k)
        boundary_edges.push_back({vertex[loop[k]], vertex[loop[(k + 1) % loop.size()]]});
    longest = std::max(longest, boxes[i].sizes().maxCoeff());
  }
  return notch_vertices(V, std::move(boundary_edges),
                        spacing > 0 ? spacing : kAutoNotchSpacing * longest);
}

// "pieces 2, 4 (mirrored): one pattern piece, cut 2; they differ by 0.33 %"
std::string group_line(const PieceGroup& g, const std::vector<PieceReport>& pieces) {
  std::string line = "pieces ";
  for (size_t k = 0; k < g.members.size(); ++k)
    line += (k ? ", " : "") + pieces[static_cast<size_t>(g.members[k])].label +
            (g.mirrored[k] ? " (mirrored)" : "");
  return line + format_text(": one pattern piece, cut %zu; they differ by %.2f %% of its size",
                            g.members.size(), g.difference);
}

}  // namespace

FlattenResult flatten(const FlattenProblem& problem, const Progress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  validate_flatten(problem);
  std::vector<Piece> pieces = extract_pieces(problem.V, problem.F, problem.patch);
  const FlattenParams& params = problem.params;

  std::vector<FlatPiece> flat(pieces.size());
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<size_t> done{0};
  const double total = static_cast<double>(pieces.size());
  {
    const SerialLibraries
        serial_libraries;  // library threads would contend with the pieces' (serial_libraries.h)
    parallel_for(pieces.size(), thread_count(params.threads), [&](size_t i) {
      const std::string what = "flattening patch " + label_of(pieces[i]);
      const auto report = [&](double fraction) {  // only the caller's thread reports
        if (progress && std::this_thread::get_id() == caller)
          progress(static_cast<int>(100.0 * (static_cast<double>(done) + fraction) / total), what);
      };
      report(0);
      flat[i] = flatten_piece(std::move(pieces[i]), params, [&](int k) {
        report(static_cast<double>(k) / std::max(1, params.max_iterations));
      });
      ++done;
    });
  }

  std::vector<Eigen::MatrixX2d> uvs;
  std::vector<Eigen::Vector2d> grain;  // on each piece as flattened, before it is turned
  for (FlatPiece& p : flat) {
    grain.push_back(grain_direction(p.piece.V, p.piece.F, p.uv, params.grain_up));
    uvs.push_back(std::move(p.uv));
  }
  const std::vector<Eigen::AlignedBox2d> boxes =
      lay_out(uvs, grain, params.gap, kAllowanceReach * params.seam_allowance);

  const std::vector<char> notch = notches_of(problem.V, flat, boxes, params.notch_spacing);

  FlattenResult r;
  r.uv.resize(problem.F.rows(), 6);
  r.stretch.resize(static_cast<size_t>(problem.F.rows()));
  std::vector<PatternPiece> pattern;
  std::string worst_label;
  for (size_t i = 0; i < flat.size(); ++i) {
    const Piece& p = flat[i].piece;
    for (int f = 0; f < p.F.rows(); ++f) {
      const int face = p.face[f];
      for (int k = 0; k < 3; ++k) r.uv.block<1, 2>(face, 2 * k) = uvs[i].row(p.F(f, k));
      r.stretch[face] = flat[i].measures.stretch[f];
    }
    std::vector<char> notched(p.vertex.size());
    for (size_t v = 0; v < notched.size(); ++v) notched[v] = notch[p.vertex[v]];
    const std::string label = label_of(p);
    pattern.push_back(pattern_piece(p.patch, label, p.F, uvs[i], flat[i].loops, notched));
    const auto name = problem.patch_names.find(p.patch);
    if (name != problem.patch_names.end()) pattern.back().name = name->second;
    pattern.back().grain = grain_rotation(grain[i]) * grain[i];
    add_seam_allowance(pattern.back(), params.seam_allowance);
    r.pieces.push_back(piece_report(flat[i], label, boxes[i]));
    r.log.push_back(log_line(r.pieces.back()));
    if (r.pieces.back().max_distortion >= r.max_distortion) {
      r.max_distortion = r.pieces.back().max_distortion;
      worst_label = label;
    }
    r.flattenable_pieces += r.pieces.back().flattenable ? 1 : 0;
  }
  r.groups = symmetric_groups(pattern, params.symmetry_tolerance);
  if (params.symmetry_tolerance > 0 && pattern.size() > kMaxSymmetryPieces)
    r.log.push_back("symmetric pieces not sought: " + std::to_string(pattern.size()) +
                    " pieces, more than " + std::to_string(kMaxSymmetryPieces) +
                    " (each would be compared with every other)");
  for (const PieceGroup& g : r.groups)
    if (g.members.size() > 1) r.log.push_back(group_line(g, r.pieces));
  const bool grouped = r.groups.size() < pattern.size();  // else the sheet is the texture layout
  r.pattern = grouped ? pattern_sheet(std::move(pattern), r.groups, sheet_gap(boxes, params.gap))
                      : make_pattern(std::move(pattern));
  r.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  r.log.push_back(
      format_text("flattened %zu pieces in %.2f s; largest length distortion %.2f %% (patch %s)",
                  r.pieces.size(), r.time_ms / 1000, r.max_distortion, worst_label.c_str()));
  if (progress) progress(100, "done");
  return r;
}

}  // namespace qd::flatten
