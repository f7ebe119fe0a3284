// The options of `quasidev approximate`, with their defaults from qd::Params.
#include <CLI/CLI.hpp>
#include <cstdlib>

#include "approximate/deformation_system.h"
#include "common/sparse_cholesky.h"
#include "option_values.h"
#include "subcommand_options.h"
#include "text_scan.h"

namespace qd::cli {

namespace {

void patch_tolerance(const std::string& text, ApproximateOptions& o) {
  const std::size_t eq = text.find('=');
  long long id = 0;
  if (eq == std::string::npos || !meshio::parse_integer(text.substr(0, eq), id) ||
      std::llabs(id) > 1000000000)
    usage("--patch-tolerance expects ID=X (e.g. 3=0.05), got '" + text + "'");
  o.patch_tolerance_ae[static_cast<int>(id)] = positive("--patch-tolerance", text.substr(eq + 1));
}

}  // namespace

void add_approximate_options(CLI::App& job, ApproximateOptions& o) {
  Params& p = o.params;
  add_job_options(job, o,
                  std::string(kInputHelp) +
                      " PLY\nvertices whose `flags` have the selection bit 0x20 are\n"
                      "constrained (never move). Polygons are fan-triangulated (said on\n"
                      "stderr).",
                  "binary little-endian PLY: same vertex and face order, x y z as\n"
                  "double, every other input property and element unchanged\n"
                  "(texture coordinates, face quality, flags, ...; vertex normals\n"
                  "are recomputed), plus vertex `quality` and a `red green blue\n"
                  "alpha` colour ramp (red = low, blue = high, range = the 2nd to\n"
                  "98th percentile). Written to a temporary file and renamed into\n"
                  "place only on success; an existing OUTPUT is left untouched on\n"
                  "error.",
                  "write every figure (per patch and per iteration) as JSON");
  valued(job, "--tolerance", "X",
         "δ_err, the largest move of a vertex in one iteration (step mode)\nor in all (total mode)" +
             by_default(o.tolerance_ae),
         [&o](const std::string& v) { o.tolerance_ae = positive("--tolerance", v); });
  choices(job, "--tolerance-mode", "M",
          "step: δ_err caps each iteration's move (paper); total: caps\nthe total move from the input",
          kToleranceModes, p.tolerance_mode);
  choices(job, "--clamp", "C",
          "step mode: scale the whole step so no vertex moves more than\nδ_err (scale), or clamp "
          "each vertex's step (vertex, paper\n§5.2)",
          kClampModes, p.clamp);
  valued(job, "--patch-tolerance", "ID=X", "δ_err for patch ID, overrides --tolerance (repeatable)",
         [&o](const std::string& v) { patch_tolerance(v, o); });
  valued(job, "--max-iter", "N", "at most N iterations per patch, N >= 1" + by_default(p.max_iter),
         [&p](const std::string& v) { p.max_iter = whole_number("--max-iter", v, 1, 100000, "1"); });
  choices(job, "--stop-rule", "R",
          "plateau: stop when the last 3 iterations together removed\nless than δ_ABD of G_ABD, "
          "keeping the best iterate;\npaper: stop at the first iteration whose ratio_ABD (Eq. "
          "19)\nis below δ_ABD, or ratio_OBD (Eq. 20) below δ_OBD with fixed\ntargets (§5.4)",
          kStopRules, p.stop_rule);
  valued(job, "--stop-abd", "P",
         "δ_ABD, percent of G_ABD (see --stop-rule)" + by_default(p.stop_abd),
         [&p](const std::string& v) { p.stop_abd = non_negative("--stop-abd", v); });
  valued(job, "--stop-obd", "P",
         "δ_OBD, percent (ratio_OBD, Eq. 20; --stop-rule paper with\n--targets fixed)" + by_default(p.stop_obd),
         [&p](const std::string& v) { p.stop_obd = non_negative("--stop-obd", v); });
  valued(job, "--weight", "W", "w of Eq. (8): developability rows vs shape rows" + by_default(p.weight),
         [&p](const std::string& v) { p.weight = positive("--weight", v); });
  valued(job, "--anchor", "A", "weight of the soft anchor rows (Eq. 15)" + by_default(p.anchor),
         [&p](const std::string& v) { p.anchor = non_negative("--anchor", v); });
  choices(job, "--developability", "D",
          "developability rows per patch: curve (the paper's target\nnormals on the Gauss-image "
          "curve), defect (Gauss-Newton rows\non the angle defects; beyond the paper, for draped "
          "panels),\nboth, or auto (each patch runs the three from the same start\nand keeps the "
          "one that removes most G_ABD; beyond the paper)",
          kDevelopability, p.developability);
  valued(job, "--defect-weight", "W",
         "w_d of the angle-defect rows, scale-invariant" + by_default(p.defect_weight),
         [&p](const std::string& v) { p.defect_weight = positive("--defect-weight", v); });
  choices(job, "--targets", "T",
          "target normals: fixed (computed once, paper), reproject\n(re-projected onto the fitted "
          "curve each iteration) or refit\n(curve re-fitted each iteration)",
          kTargetModes, p.targets);
  choices(job, "--seams", "S",
          "fixed: seam vertices between patches do not move (paper);\nfree: all patches solved "
          "jointly, seams move and stay\nclosed",
          kSeamModes, p.seams);
  choices(job, "--segment-first", "S",
          "a mesh without patch ids: auto splits it into nearly\ndevelopable patches first (segment, "
          "largest fit error 30\ndegrees) and solves them with free seams when it is closed\nor no "
          "one Gauss-image curve fits it; never keeps it one\npatch; always splits it",
          kSegmentFirst, p.segment_first);
  choices(job, "--solver", "S",
          "sparse Cholesky: cholmod (SuiteSparse supernodal), eigen-llt,\neigen-ldlt (Eigen's "
          "simplicial) or auto (eigen-ldlt below\n" + std::to_string(kCholmodFromUnknowns) +
              " unknowns per patch, else cholmod); same\nresult. Patches with angle-defect rows "
              "solve their\nquasi-definite system by LDLT: our supernodal LDLT\n(auto, "
              "cholmod) or Eigen's simplicial LDLT\n(eigen-llt, eigen-ldlt)",
          kSolverKinds, p.solver);
  std::ostringstream method;
  method << "direct: factorise the coupled system; iterative: conjugate\ngradients with two scalar "
            "factors, to a relative error of\n"
         << kCgTolerance << "; auto: iterative from " << kIterativeFromUnknowns
         << " unknowns\nper patch; patches with angle-defect rows are always\nfactorised";
  choices(job, "--method", "M", method.str(), kSolveMethods, p.method);
  valued(job, "--threads", "N",
         "patches solved at once (fixed seams); 0 = all cores; the\nresult does not depend on it" +
             by_default(p.threads),
         [&p](const std::string& v) { p.threads = whole_number("--threads", v, 0, 1024, "0 (all cores)"); });
  const auto on = [](bool b) { return std::string(b ? " (default)" : ""); };
  flag(job, "--keep-boundary", "open-boundary vertices do not move" + on(p.keep_boundary),
       [&p] { p.keep_boundary = true; });
  flag(job, "--free-boundary", "open-boundary vertices may move" + on(!p.keep_boundary),
       [&p] { p.keep_boundary = false; });
  valued(job, "--constraints", "FILE",
         "vertices that must not move: 0-based indices, one per line,\n'#' starts a comment "
         "(added to the PLY selection)",
         [&o](const std::string& v) { o.constraints = v; });
  choices(job, "--quality", "Q",
          "vertex quality written: curvature (Gaussian curvature K after)\nor displacement "
          "(|v' - v|, model units)",
          kQualityKinds, o.quality);
  flag(job, "--no-color", "write no colour ramp (the input's vertex colours are kept)",
       [&o] { o.color = false; });
}

}  // namespace qd::cli
