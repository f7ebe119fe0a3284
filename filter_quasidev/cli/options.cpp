#include "options.h"

#include <cmath>
#include <functional>
#include <sstream>

#include "approximate/deformation_system.h"
#include "common/sparse_cholesky.h"
#include "text_scan.h"

namespace qd::cli {

namespace {

[[noreturn]] void usage(const std::string& message) {
  throw UsageError(message + " (see quasidev --help)");
}

double number(const std::string& option, const std::string& text) {
  double v = 0;
  if (!meshio::parse_number(text, v) || !std::isfinite(v))
    usage(option + " expects a finite number, got '" + text + "'");
  return v;
}

double positive(const std::string& option, const std::string& text) {
  const double v = number(option, text);
  if (v <= 0) usage(option + " must be greater than 0, got " + text);
  return v;
}

double non_negative(const std::string& option, const std::string& text) {
  const double v = number(option, text);
  if (v < 0) usage(option + " must not be negative, got " + text);
  return v;
}

// A whole number in [lo, hi]; `lo_label` names lo in the message (e.g. "0 (all cores)").
int whole_number(const std::string& option, const std::string& text, long long lo, long long hi,
                 const std::string& lo_label) {
  long long v = 0;
  if (!meshio::parse_integer(text, v) || v < lo || v > hi)
    usage(option + " expects a whole number from " + lo_label + " to " + std::to_string(hi) +
          ", got '" + text + "'");
  return static_cast<int>(v);
}

// Value of an option of fixed choices, e.g. step|total.
template <typename T>
T choice(const std::string& option, const std::string& text,
         const std::vector<std::pair<const char*, T>>& choices) {
  std::string names;
  for (const auto& [name, value] : choices) {
    if (text == name) return value;
    names += (names.empty() ? "" : "|") + std::string(name);
  }
  usage(option + " expects " + names + ", got '" + text + "'");
}

void patch_tolerance(const std::string& text, Options& o) {
  const std::size_t eq = text.find('=');
  long long id = 0;
  if (eq == std::string::npos || !meshio::parse_integer(text.substr(0, eq), id) ||
      std::llabs(id) > 1000000000)
    usage("--patch-tolerance expects ID=X (e.g. 3=0.05), got '" + text + "'");
  o.patch_tolerance_ae[static_cast<int>(id)] = positive("--patch-tolerance", text.substr(eq + 1));
}

using Setter = std::function<void(Options&, const std::string&)>;

// Options that take a value.
const std::map<std::string, Setter>& valued_options() {
  static const std::map<std::string, Setter> table = {
      {"--report", [](Options& o, const std::string& v) { o.report = v; }},
      {"--constraints", [](Options& o, const std::string& v) { o.constraints = v; }},
      {"--tolerance", [](Options& o, const std::string& v) { o.tolerance_ae = positive("--tolerance", v); }},
      {"--patch-tolerance", [](Options& o, const std::string& v) { patch_tolerance(v, o); }},
      {"--tolerance-mode",
       [](Options& o, const std::string& v) {
         o.params.tolerance_mode = choice<ToleranceMode>(
             "--tolerance-mode", v, {{"step", ToleranceMode::Step}, {"total", ToleranceMode::Total}});
       }},
      {"--clamp",
       [](Options& o, const std::string& v) {
         o.params.clamp = choice<ClampMode>("--clamp", v,
                                            {{"scale", ClampMode::Scale}, {"vertex", ClampMode::Vertex}});
       }},
      {"--max-iter", [](Options& o, const std::string& v) { o.params.max_iter = whole_number("--max-iter", v, 1, 100000, "1"); }},
      {"--weight", [](Options& o, const std::string& v) { o.params.weight = positive("--weight", v); }},
      {"--anchor", [](Options& o, const std::string& v) { o.params.anchor = non_negative("--anchor", v); }},
      {"--developability",
       [](Options& o, const std::string& v) {
         o.params.developability = choice<Developability>(
             "--developability", v,
             {{"curve", Developability::Curve}, {"defect", Developability::Defect},
              {"both", Developability::Both}, {"auto", Developability::Auto}});
       }},
      {"--defect-weight", [](Options& o, const std::string& v) { o.params.defect_weight = positive("--defect-weight", v); }},
      {"--seams",
       [](Options& o, const std::string& v) {
         o.params.seams = choice<SeamMode>("--seams", v, {{"fixed", SeamMode::Fixed}, {"free", SeamMode::Free}});
       }},
      {"--targets",
       [](Options& o, const std::string& v) {
         o.params.targets = choice<TargetMode>(
             "--targets", v,
             {{"fixed", TargetMode::Fixed}, {"reproject", TargetMode::Reproject}, {"refit", TargetMode::Refit}});
       }},
      {"--solver",
       [](Options& o, const std::string& v) {
         o.params.solver = choice<SolverKind>("--solver", v,
                                              {{"auto", SolverKind::Auto},
                                               {"cholmod", SolverKind::Cholmod},
                                               {"eigen-llt", SolverKind::EigenLLT},
                                               {"eigen-ldlt", SolverKind::EigenLDLT}});
       }},
      {"--method",
       [](Options& o, const std::string& v) {
         o.params.method = choice<SolveMethod>(
             "--method", v,
             {{"auto", SolveMethod::Auto}, {"direct", SolveMethod::Direct}, {"iterative", SolveMethod::Iterative}});
       }},
      {"--threads", [](Options& o, const std::string& v) { o.params.threads = whole_number("--threads", v, 0, 1024, "0 (all cores)"); }},
      {"--stop-abd", [](Options& o, const std::string& v) { o.params.stop_abd = non_negative("--stop-abd", v); }},
      {"--stop-obd", [](Options& o, const std::string& v) { o.params.stop_obd = non_negative("--stop-obd", v); }},
      {"--quality",
       [](Options& o, const std::string& v) {
         o.quality = choice<QualityKind>(
             "--quality", v, {{"curvature", QualityKind::Curvature}, {"displacement", QualityKind::Displacement}});
       }},
  };
  return table;
}

// Options without a value.
const std::map<std::string, std::function<void(Options&)>>& flag_options() {
  static const std::map<std::string, std::function<void(Options&)>> table = {
      {"--keep-boundary", [](Options& o) { o.params.keep_boundary = true; }},
      {"--free-boundary", [](Options& o) { o.params.keep_boundary = false; }},
      {"--no-color", [](Options& o) { o.color = false; }},
      {"--progress", [](Options& o) { o.progress = ProgressMode::On; }},
      {"--no-progress", [](Options& o) { o.progress = ProgressMode::Off; }},
      {"--quiet", [](Options& o) { o.quiet = true; }},
      {"--overwrite-input", [](Options& o) { o.overwrite_input = true; }},
      {"--help", [](Options& o) { o.help = true; }},
      {"-h", [](Options& o) { o.help = true; }},
      {"--version", [](Options& o) { o.version = true; }},
  };
  return table;
}

}  // namespace

Options parse_options(const std::vector<std::string>& args) {
  Options o;
  std::vector<std::string> positional;
  bool only_positional = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (only_positional || a.size() < 2 || a[0] != '-') {
      positional.push_back(a);
      continue;
    }
    if (a == "--") {
      only_positional = true;
      continue;
    }
    const std::size_t eq = a.find('=');
    const std::string name = a.substr(0, eq);
    const auto valued = valued_options().find(name);
    if (valued != valued_options().end()) {
      if (eq == std::string::npos && i + 1 >= args.size()) usage(name + " needs a value");
      valued->second(o, eq == std::string::npos ? args[++i] : a.substr(eq + 1));
      continue;
    }
    const auto flag = flag_options().find(a);
    if (flag == flag_options().end()) usage("unknown option '" + a + "'");
    flag->second(o);
  }
  if (o.help || o.version) return o;
  if (positional.size() != 2)
    usage("expected INPUT and OUTPUT, got " + std::to_string(positional.size()) + " file name(s)");
  o.input = positional[0];
  o.output = positional[1];
  if (o.output == o.input && !o.overwrite_input)
    usage("OUTPUT is the INPUT file; pass --overwrite-input to replace it");
  if (!o.report.empty() && (o.report == o.output || o.report == o.input))
    usage("the --report file must differ from INPUT and OUTPUT");
  return o;
}

std::string help_text() {
  const Params d;
  const auto on_off = [](bool b) { return b ? " (default)" : ""; };
  std::ostringstream h;
  h << "Usage: quasidev INPUT OUTPUT [options]\n"
       "\n"
       "Makes the patches of a triangle mesh nearly developable (Zeng et al., \"Least squares\n"
       "quasi-developable mesh approximation\", CAGD 2012) and writes the result as a binary PLY.\n"
       "\n"
       "INPUT   PLY (ascii or binary), OBJ or OFF. Patches come from the PLY face `quality`\n"
       "        (rounded; else an integer face `patch`) or OBJ `g`/`o` groups; without them the\n"
       "        whole mesh is one patch. PLY vertices whose `flags` have the selection bit 0x20\n"
       "        are constrained (never move). Polygons are fan-triangulated (said on stderr).\n"
       "OUTPUT  binary little-endian PLY: same vertex and face order, x y z as double, every\n"
       "        other input property and element unchanged (texture coordinates, face quality,\n"
       "        flags, ...; vertex normals are recomputed), plus vertex `quality` and a\n"
       "        `red green blue alpha` colour ramp (red = low, blue = high, range = the 2nd to\n"
       "        98th percentile). Written to a temporary file and renamed into place only on\n"
       "        success; an existing OUTPUT is left untouched on error.\n"
       "\n"
       "Lengths X are in units of AE, the input's average edge length.\n"
       "\n"
       "  --tolerance X          δ_err, the largest move of a vertex in one iteration (step\n"
       "                         mode) or in all (total mode) (default "
    << kDefaultToleranceAE << ")\n"
    << "  --tolerance-mode M     step: δ_err caps each iteration's move (paper); total: caps the\n"
       "                         total move from the input (default "
    << (d.tolerance_mode == ToleranceMode::Step ? "step" : "total") << ")\n"
    << "  --clamp C              step mode: scale the whole step so no vertex moves more than\n"
       "                         δ_err (scale), or clamp each vertex's step (vertex, paper §5.2)\n"
       "                         (default "
    << (d.clamp == ClampMode::Scale ? "scale" : "vertex") << ")\n"
    << "  --patch-tolerance ID=X δ_err for patch ID, overrides --tolerance (repeatable)\n"
    << "  --max-iter N           at most N iterations per patch, N >= 1 (default " << d.max_iter << ")\n"
    << "  --stop-abd P           stop when G_ABD falls by less than P percent in an iteration\n"
       "                         (ratio_ABD, Eq. 19; default "
    << d.stop_abd << ")\n"
    << "  --stop-obd P           stop when the OBD falls by less than P percent (ratio_OBD,\n"
       "                         Eq. 20; default "
    << d.stop_obd << ")\n"
    << "  --weight W             w of Eq. (8): developability rows vs shape rows (default " << d.weight << ")\n"
    << "  --anchor A             weight of the soft anchor rows (Eq. 15) (default " << d.anchor << ")\n"
    << "  --developability D     developability rows per patch: curve (the paper's target\n"
       "                         normals on the Gauss-image curve), defect (Gauss-Newton rows\n"
       "                         on the angle defects; beyond the paper, for draped panels),\n"
       "                         both, or auto (curve up to a fit residual of 5 degrees, else\n"
       "                         defect; beyond the paper) (default auto)\n"
    << "  --defect-weight W      w_d of the angle-defect rows, scale-invariant (default " << d.defect_weight << ")\n"
    << "  --targets T            target normals: fixed (computed once, paper), reproject\n"
       "                         (re-projected onto the fitted curve each iteration) or refit\n"
       "                         (curve re-fitted each iteration) (default "
    << (d.targets == TargetMode::Fixed ? "fixed" : d.targets == TargetMode::Reproject ? "reproject" : "refit")
    << ")\n"
    << "  --seams S              fixed: seam vertices between patches do not move (paper);\n"
       "                         free: all patches solved jointly, seams move and stay closed\n"
       "                         (default "
    << (d.seams == SeamMode::Fixed ? "fixed" : "free") << ")\n"
    << "  --solver S             sparse Cholesky: cholmod (SuiteSparse supernodal), eigen-llt,\n"
       "                         eigen-ldlt (Eigen's simplicial) or auto (eigen-ldlt below\n"
       "                         " << kCholmodFromUnknowns << " unknowns per patch, else cholmod); same result (default auto)\n"
    << "  --method M             direct: factorise the coupled system; iterative: conjugate\n"
       "                         gradients with two scalar factors, to a relative error of\n"
       "                         " << kCgTolerance << "; auto: iterative from " << kIterativeFromUnknowns << " unknowns per patch\n"
       "                         (default auto)\n"
    << "  --threads N            patches solved at once (fixed seams); 0 = all cores; the\n"
       "                         result does not depend on it (default " << d.threads << ")\n"
    << "  --keep-boundary        open-boundary vertices do not move" << on_off(d.keep_boundary) << "\n"
    << "  --free-boundary        open-boundary vertices may move" << on_off(!d.keep_boundary) << "\n"
    << "  --constraints FILE     vertices that must not move: 0-based indices, one per line,\n"
       "                         '#' starts a comment (added to the PLY selection)\n"
       "  --quality Q            vertex quality written: curvature (Gaussian curvature K after)\n"
       "                         or displacement (|v' - v|, model units) (default curvature)\n"
       "  --no-color             write no colour ramp (the input's vertex colours are kept)\n"
       "  --report FILE.json     write every figure (per patch and per iteration) as JSON\n"
       "  --overwrite-input      allow OUTPUT to be the INPUT file\n"
       "  --progress             show a progress line on stderr (default: when stderr is a\n"
       "                         terminal); --no-progress never shows it\n"
       "  --quiet                print neither the per-patch log (stdout) nor notes (stderr)\n"
       "  --version              print the version and exit\n"
       "  -h, --help             print this help and exit\n"
       "\n"
       "Exit status: 0 success; 1 bad input or engine error; 2 bad command line. On error one\n"
       "line 'quasidev: error: REASON' goes to stderr and OUTPUT is not written.\n";
  return h.str();
}

}  // namespace qd::cli
