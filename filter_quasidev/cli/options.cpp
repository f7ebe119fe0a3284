// CLI11 parses the command line's shape (subcommands, options anywhere, --opt=value, --,
// repeated options, help); each value is converted here or in the subcommand's own options file
// (segment_options.cpp) with the converters of option_values.h, so every message keeps the
// command's wording: the option, the bad value and what to do.
#include "options.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "approximate/deformation_system.h"
#include "common/sparse_cholesky.h"
#include "option_values.h"
#include "segment_options.h"
#include "text_scan.h"

namespace qd::cli {

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

int whole_number(const std::string& option, const std::string& text, long long lo, long long hi,
                 const std::string& lo_label) {
  long long v = 0;
  if (!meshio::parse_integer(text, v) || v < lo || v > hi)
    usage(option + " expects a whole number from " + lo_label + " to " + std::to_string(hi) +
          ", got '" + text + "'");
  return static_cast<int>(v);
}

void valued(CLI::App& job, const std::string& name, const std::string& value_name,
            const std::string& description, std::function<void(const std::string&)> set) {
  job.add_option_function<std::string>(name, std::move(set), description)
      ->option_text(value_name)
      ->trigger_on_parse();
}

void flag(CLI::App& job, const std::string& name, const std::string& description,
          std::function<void()> set) {
  job.add_flag_callback(name, std::move(set), description)->trigger_on_parse();
}

void add_progress_flags(CLI::App& job, ProgressMode& progress, bool& quiet) {
  flag(job, "--progress",
       "show a progress line on stderr (default: when stderr is a\nterminal and not --quiet)",
       [&progress] { progress = ProgressMode::On; });
  flag(job, "--no-progress", "never show the progress line", [&progress] { progress = ProgressMode::Off; });
  flag(job, "--quiet", "print neither the per-patch log (stdout) nor notes (stderr)",
       [&quiet] { quiet = true; });
}

namespace {

void patch_tolerance(const std::string& text, Options& o) {
  const std::size_t eq = text.find('=');
  long long id = 0;
  if (eq == std::string::npos || !meshio::parse_integer(text.substr(0, eq), id) ||
      std::llabs(id) > 1000000000)
    usage("--patch-tolerance expects ID=X (e.g. 3=0.05), got '" + text + "'");
  o.patch_tolerance_ae[static_cast<int>(id)] = positive("--patch-tolerance", text.substr(eq + 1));
}

void add_approximate_options(CLI::App& job, Options& o) {
  Params& p = o.params;
  job.add_option("INPUT", o.input,
                 "PLY (ascii or binary), OBJ or OFF. Patches come from the PLY\n"
                 "face `quality` (rounded; else an integer face `patch`) or OBJ\n"
                 "`g`/`o` groups; without them the whole mesh is one patch. PLY\n"
                 "vertices whose `flags` have the selection bit 0x20 are\n"
                 "constrained (never move). Polygons are fan-triangulated (said on\n"
                 "stderr).")
      ->required()
      ->type_name("");
  job.add_option("OUTPUT", o.output,
                 "binary little-endian PLY: same vertex and face order, x y z as\n"
                 "double, every other input property and element unchanged\n"
                 "(texture coordinates, face quality, flags, ...; vertex normals\n"
                 "are recomputed), plus vertex `quality` and a `red green blue\n"
                 "alpha` colour ramp (red = low, blue = high, range = the 2nd to\n"
                 "98th percentile). Written to a temporary file and renamed into\n"
                 "place only on success; an existing OUTPUT is left untouched on\n"
                 "error.")
      ->required()
      ->type_name("");
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
  valued(job, "--stop-abd", "P",
         "stop when G_ABD falls by less than P percent in an iteration\n(ratio_ABD, Eq. 19)" +
             by_default(p.stop_abd),
         [&p](const std::string& v) { p.stop_abd = non_negative("--stop-abd", v); });
  valued(job, "--stop-obd", "P",
         "stop when the OBD falls by less than P percent (ratio_OBD,\nEq. 20)" + by_default(p.stop_obd),
         [&p](const std::string& v) { p.stop_obd = non_negative("--stop-obd", v); });
  valued(job, "--weight", "W", "w of Eq. (8): developability rows vs shape rows" + by_default(p.weight),
         [&p](const std::string& v) { p.weight = positive("--weight", v); });
  valued(job, "--anchor", "A", "weight of the soft anchor rows (Eq. 15)" + by_default(p.anchor),
         [&p](const std::string& v) { p.anchor = non_negative("--anchor", v); });
  choices(job, "--developability", "D",
          "developability rows per patch: curve (the paper's target\nnormals on the Gauss-image "
          "curve), defect (Gauss-Newton rows\non the angle defects; beyond the paper, for draped "
          "panels),\nboth, or auto (curve up to a fit residual of 5 degrees, else\ndefect; beyond "
          "the paper)",
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
  choices(job, "--solver", "S",
          "sparse Cholesky: cholmod (SuiteSparse supernodal), eigen-llt,\neigen-ldlt (Eigen's "
          "simplicial) or auto (eigen-ldlt below\n" + std::to_string(kCholmodFromUnknowns) +
              " unknowns per patch, else cholmod); same\nresult",
          kSolverKinds, p.solver);
  std::ostringstream method;
  method << "direct: factorise the coupled system; iterative: conjugate\ngradients with two scalar "
            "factors, to a relative error of\n"
         << kCgTolerance << "; auto: iterative from " << kIterativeFromUnknowns
         << " unknowns\nper patch";
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
  valued(job, "--report", "FILE.json", "write every figure (per patch and per iteration) as JSON",
         [&o](const std::string& v) { o.report = v; });
  flag(job, "--overwrite-input", "allow OUTPUT to be the INPUT file", [&o] { o.overwrite_input = true; });
  add_progress_flags(job, o.progress, o.quiet);
}

// --help and --version, which every level of the command has; the footer is inherited.
void add_help_and_version(CLI::App& app) {
  app.set_help_flag("-h,--help", "print this help and exit");
  app.set_version_flag("--version", std::string("quasidev ") + QD_VERSION, "print the version and exit");
}

// Unknown options first, then the number of file names, as the command has always checked.
void check_leftovers(const CLI::App& job) {
  std::size_t files = job.count("INPUT") + job.count("OUTPUT");
  bool only_files = false;
  for (const std::string& a : job.remaining()) {
    if (a == "--") {
      only_files = true;
      continue;
    }
    if (!only_files && a.size() >= 2 && a[0] == '-') usage("unknown option '" + a + "'");
    ++files;
  }
  if (files != 2) usage("expected INPUT and OUTPUT, got " + std::to_string(files) + " file name(s)");
}

template <typename JobOptions>
void check_files(const JobOptions& o) {
  if (o.output == o.input && !o.overwrite_input)
    usage("OUTPUT is the INPUT file; pass --overwrite-input to replace it");
  if (!o.report.empty() && (o.report == o.output || o.report == o.input))
    usage("the --report file must differ from INPUT and OUTPUT");
}

}  // namespace

CommandLine parse_command_line(std::vector<std::string> args) {
  CommandLine line;
  CLI::App app("Makes triangle mesh patches nearly developable: cuttable from flat sheet\n"
               "material without stretching. Without a subcommand, `quasidev INPUT OUTPUT\n"
               "[options]` runs `approximate`.\n",
               "quasidev");
  app.get_formatter()->column_width(25);
  app.footer("Lengths X are in units of AE, the input's average edge length.\n"
             "Exit status: 0 success; 1 bad input or engine error; 2 bad command line. On error\n"
             "one line 'quasidev: error: REASON' goes to stderr and OUTPUT is not written.");
  add_help_and_version(app);
  CLI::App* approximate = app.add_subcommand(
      "approximate",
      "Makes the patches of a triangle mesh nearly developable (Zeng et al., \"Least squares\n"
      "quasi-developable mesh approximation\", CAGD 2012) and writes the result as a binary PLY.\n");
  add_help_and_version(*approximate);
  approximate->allow_extras();
  add_approximate_options(*approximate, line.approximate);
  CLI::App* segment = app.add_subcommand(
      "segment",
      "Splits a triangle mesh into nearly developable patches (D-Charts: Julius, Kraevoy,\n"
      "Sheffer, Eurographics 2005) and writes it as a binary PLY with the patch id per face.\n");
  add_help_and_version(*segment);
  segment->allow_extras();
  add_segment_options(*segment, line.segment);
  // The subcommand `flatten` joins here, with add_progress_flags.
  const bool names_job =
      !args.empty() && (args[0] == "-h" || args[0] == "--help" || args[0] == "--version" ||
                        !app.get_subcommands([&](const CLI::App* s) { return s->check_name(args[0]); })
                             .empty());
  if (!names_job) args.insert(args.begin(), approximate->get_name());
  line.job = segment->check_name(args[0]) ? Job::Segment : Job::Approximate;
  const CLI::App& job = line.job == Job::Segment ? *segment : *approximate;
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last first
  try {
    app.parse(args);
  } catch (const CLI::CallForHelp&) {
    line.print = app.help("", CLI::AppFormatMode::All);
    return line;
  } catch (const CLI::CallForVersion& e) {
    line.print = std::string(e.what()) + "\n";
    return line;
  } catch (const CLI::ArgumentMismatch& e) {  // "NAME: 1 required TEXT missing"
    const std::string what = e.what();
    usage(what.substr(0, what.find(':')) + " needs a value");
  } catch (const CLI::RequiredError&) {  // INPUT or OUTPUT missing
    check_leftovers(job);
  } catch (const CLI::ParseError& e) {
    usage(e.what());
  }
  check_leftovers(job);
  if (line.job == Job::Segment)
    check_files(line.segment);
  else
    check_files(line.approximate);
  return line;
}

}  // namespace qd::cli
