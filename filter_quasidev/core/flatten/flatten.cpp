#include "flatten/flatten.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <thread>

#include "error.h"
#include "flatten/flatten_piece.h"
#include "flatten/layout.h"
#include "flatten/notches.h"
#include "parallel_for.h"
#include "serial_blas.h"
#include "validate.h"

namespace qd {

namespace {

constexpr double kAutoNotchSpacing = 0.125;  // of the largest piece's longer side

// The mesh checks of the approximation (validate.h) with neutral parameters: nothing
// constrained, so only what makes a mesh unusable fails.
void validate_mesh(const FlattenProblem& problem) {
  Problem check;
  check.V = problem.V;
  check.F = problem.F;
  check.patch = problem.patch;
  check.params.tolerance = 1;
  check.params.seams = SeamMode::Free;
  check.params.keep_boundary = false;
  validate(check);
}

std::string str(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

void check_params(const FlattenParams& q) {
  if (q.max_iterations < 0 || q.max_iterations > 100000)
    throw Error("The maximum number of ARAP iterations is " + std::to_string(q.max_iterations) +
                ": use a value from 0 (the initial layout only) to 100000, e.g. 100.");
  if (!std::isfinite(q.tolerance) || q.tolerance < 0 || q.tolerance >= 1)
    throw Error("The ARAP tolerance is " + str(q.tolerance) +
                ": it is a relative change of the energy, use a value in [0, 1), e.g. 1e-4.");
  if (!std::isfinite(q.gap) || q.gap < 0)
    throw Error("The gap between pieces is " + str(q.gap) + ": use a distance >= 0 (0 = automatic).");
  if (!std::isfinite(q.notch_spacing) || q.notch_spacing < 0)
    throw Error("The notch spacing is " + str(q.notch_spacing) + ": use a distance >= 0 (0 = automatic).");
  if (q.threads < 0)
    throw Error("The number of threads is " + std::to_string(q.threads) + ": use 0 (all cores) or more.");
}

std::string label_of(const Piece& p) {
  return std::to_string(p.patch) + (p.components > 1 ? "." + std::to_string(p.component) : "");
}

PieceReport report_of(const FlatPiece& flat, const std::string& label, const Eigen::AlignedBox2d& box) {
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
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << std::showpos;
  s << "patch " << r.label << ": " << std::noshowpos << r.faces << " faces";
  if (!r.cut.empty()) s << ", " << r.cut;
  s << "; " << r.iterations << " ARAP iterations (" << r.stop_reason << "); length distortion max "
    << r.max_distortion << " %, mean " << r.mean_distortion << " %; area " << std::showpos << r.area_change
    << " %, boundary " << r.boundary_change << " %; " << std::noshowpos << r.flipped << " flipped, "
    << r.overlapping << " overlapping";
  if (!r.flattenable) s << ": not flattenable without a cut";
  return s.str();
}

size_t thread_count(int requested) {
  return requested > 0 ? static_cast<size_t>(requested) : std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace

FlattenResult flatten(const FlattenProblem& problem, const Progress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  validate_mesh(problem);
  check_params(problem.params);
  std::vector<Piece> pieces = extract_pieces(problem.V, problem.F, problem.patch);
  const FlattenParams& params = problem.params;

  std::vector<FlatPiece> flat(pieces.size());
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<size_t> done{0};
  const double total = static_cast<double>(pieces.size());
  {
    const SerialBlas serial_blas;  // BLAS threads would contend with the pieces' (serial_blas.h)
    parallel_for(pieces.size(), thread_count(params.threads), [&](size_t i) {
      const std::string what = "flattening patch " + label_of(pieces[i]);
      const auto report = [&](double fraction) {  // only the caller's thread reports
        if (progress && std::this_thread::get_id() == caller)
          progress(static_cast<int>(100.0 * (static_cast<double>(done) + fraction) / total), what);
      };
      report(0);
      flat[i] = flatten_piece(std::move(pieces[i]), params,
                              [&](int k) { report(static_cast<double>(k) / std::max(1, params.max_iterations)); });
      ++done;
    });
  }

  std::vector<Eigen::MatrixX2d> uvs;
  for (FlatPiece& p : flat) uvs.push_back(std::move(p.uv));
  const std::vector<Eigen::AlignedBox2d> boxes = lay_out(uvs, params.gap);

  std::vector<std::array<int, 2>> boundary_edges;  // all pieces', in mesh vertices
  double longest = 0;
  for (size_t i = 0; i < flat.size(); ++i) {
    for (const std::vector<int>& loop : flat[i].loops)
      for (size_t k = 0; k < loop.size(); ++k)
        boundary_edges.push_back({flat[i].piece.vertex[loop[k]], flat[i].piece.vertex[loop[(k + 1) % loop.size()]]});
    longest = std::max(longest, boxes[i].sizes().maxCoeff());
  }
  const std::vector<char> notch = notch_vertices(problem.V, std::move(boundary_edges),
                                                 params.notch_spacing > 0 ? params.notch_spacing : kAutoNotchSpacing * longest);

  FlattenResult r;
  r.uv.resize(problem.F.rows(), 6);
  r.stretch.resize(static_cast<size_t>(problem.F.rows()));
  std::vector<PatternPiece> pattern;
  double worst = 0;
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
    r.pieces.push_back(report_of(flat[i], label, boxes[i]));
    r.log.push_back(log_line(r.pieces.back()));
    if (r.pieces.back().max_distortion >= worst) {
      worst = r.pieces.back().max_distortion;
      worst_label = label;
    }
  }
  r.pattern = make_pattern(std::move(pattern));
  r.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::ostringstream total_line;
  total_line << std::fixed << std::setprecision(2) << "flattened " << r.pieces.size() << " pieces in " << r.time_ms / 1000
             << " s; largest length distortion " << worst << " % (patch " << worst_label << ")";
  r.log.push_back(total_line.str());
  if (progress) progress(100, "done");
  return r;
}

}  // namespace qd
