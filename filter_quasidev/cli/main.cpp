// quasidev [approximate]: reads a mesh, runs the quasi-developable approximation (qd::approximate),
// writes the deformed mesh as PLY with per-vertex quality and a colour ramp, and optionally a JSON
// report. quasidev segment: reads a mesh, splits it into nearly developable patches
// (qd::segment), writes it as PLY with per-face quality = patch id and a colour per patch, and
// optionally a JSON report. quasidev flatten: reads a mesh, flattens its patches (qd::flatten),
// writes it as PLY with wedge texture coordinates, the stretch per face and its colour ramp, and
// optionally a JSON report and the pattern as SVG, DXF and a printable PDF. Subcommands and
// options: options.h. Exit 0 on success; 1 on bad input or an engine error; 2 on a bad command
// line. On error one line "quasidev: error: REASON" goes to stderr and no file is written.
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "approximate/quasidev.h"
#include "approximate_params.h"
#include "approximate_report_json.h"
#include "blas_kernels.h"
#include "common/format_text.h"
#include "cut_marker.h"
#include "flatten/flatten.h"
#include "flatten_mesh.h"
#include "io/atomic_file.h"
#include "io/mesh_reader.h"
#include "io/output_mesh.h"
#include "io/pattern_files.h"
#include "io/result_document.h"
#include "marker_dxf.h"
#include "marker_report_json.h"
#include "marker_svg.h"
#include "mesh_problem.h"
#include "options.h"
#include "printable_pdf.h"
#include "python_batch.h"
#include "segment/segment.h"
#include "segment_mesh.h"
#include "segment_report_json.h"

namespace {

// The progress line on stderr: rewritten in place ("\r") on a terminal, else one line per
// change of percentage. Closed with a newline before anything else is printed to stderr.
class ProgressLine {
 public:
  void enable() {
    enabled_ = true;
    terminal_ = isatty(STDERR_FILENO) != 0;
  }
  void show(int percent, const std::string& message) {
    if (!enabled_ || (!terminal_ && percent == last_percent_)) return;
    last_percent_ = percent;
    const std::string text = "quasidev: " + std::to_string(percent) + "% " + message.substr(0, 60);
    if (terminal_) {
      std::cerr << '\r' << text << "\x1b[K" << std::flush;
      open_ = true;
    } else {
      std::cerr << text << std::endl;
    }
  }
  void close() {
    if (open_) std::cerr << '\n';
    open_ = false;
  }

 private:
  bool enabled_ = false;
  bool terminal_ = false;
  bool open_ = false;
  int last_percent_ = -1;
};

ProgressLine progress_line;

// Refuses to replace the input (unless asked) or to write two outputs into one file, comparing
// the files themselves (options.cpp compared their names).
void check_paths(const qd::cli::JobOptions& o,
                 const std::vector<std::pair<std::string, std::string>>& outputs) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto same = [&ec](const std::string& a, const std::string& b) {
    return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec);
  };
  if (!o.overwrite_input && same(o.input, o.output))
    throw qd::cli::UsageError("OUTPUT is the INPUT file; pass --overwrite-input to replace it");
  for (std::size_t i = 1; i < outputs.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (same(outputs[i].second, o.input) || same(outputs[i].second, outputs[j].second))
        throw qd::cli::UsageError("the " + outputs[i].first +
                                  " file must differ from INPUT, OUTPUT and the other files");
}

void start_progress(const qd::cli::JobOptions& o) {
  if (o.progress == qd::cli::ProgressMode::On ||
      (o.progress == qd::cli::ProgressMode::Auto && !o.quiet && isatty(STDERR_FILENO)))
    progress_line.enable();
}

const qd::common::Progress show_progress = [](int percent, const std::string& message) {
  progress_line.show(percent, message);
};

// Stages every file of a job (target, content) before renaming any into place, so an error
// while writing leaves all of them as they were.
void write_files(const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<std::unique_ptr<qd::io::PendingFile>> pending;
  for (const auto& [target, content] : files)
    pending.push_back(std::make_unique<qd::io::PendingFile>(target, content));
  for (const auto& file : pending) file->commit();
}

std::string ply_bytes(const qd::io::MeshDocument& doc) {
  return qd::io::serialize_ply(doc, qd::io::PlyFormat::BinaryLittleEndian);
}

// True when a log line is one of the warnings (the engines log each one, bare or after
// "warning: ", for the MeshLab log, which is their only channel there).
bool is_warning(const std::string& line, const std::vector<std::string>& warnings) {
  return std::any_of(warnings.begin(), warnings.end(), [&line](const std::string& w) {
    return line == w || line == "warning: " + w;
  });
}

// Each warning once, on stderr, even with --quiet (it says part of the mesh was handled
// specially, like an error would); then, unless --quiet, the job's other log lines on stdout
// and the reader's notes on stderr.
void print_outcome(const qd::cli::JobOptions& o, const std::vector<std::string>& warnings,
                   const std::vector<std::string>& log, const std::vector<std::string>& notes) {
  for (const std::string& warning : warnings) std::cerr << "quasidev: warning: " << warning << '\n';
  if (o.quiet) return;
  for (const std::string& line : log)
    if (!is_warning(line, warnings)) std::cout << line << '\n';
  for (const std::string& note : notes) std::cerr << "quasidev: note: " << note << '\n';
}

int count_constrained(const std::vector<char>& constrained) {
  int n = 0;
  for (char c : constrained) n += c ? 1 : 0;
  return n;
}

// What every job does before writing: refuse clashing files, read INPUT, build the engine's
// problem (make_problem(mesh)) and solve it (solve(problem, progress)) with the progress line.
template <typename Options, typename MakeProblem, typename Solve>
auto read_and_solve(const Options& o, MakeProblem make_problem, Solve solve) {
  check_paths(o, qd::cli::output_files(o));
  qd::io::MeshDocument mesh = qd::io::read_mesh(o.input);
  auto problem = make_problem(mesh);
  start_progress(o);
  auto result = solve(problem, show_progress);
  progress_line.close();
  return std::make_tuple(std::move(mesh), std::move(problem), std::move(result));
}

// A parameter's setting in the engine's log as the command is given it: "--name value".
std::string option_setting(const std::string& name, const std::string& value) {
  const auto& declared = qd::params::approximate_params();
  const bool known = std::any_of(declared.begin(), declared.end(),
                                 [&](const qd::params::ParamInfo& p) { return p.name == name; });
  return known ? qd::params::option_name(name) + " " + value : name + " = " + value;
}

void approximate(const qd::cli::ApproximateOptions& o) {
  const auto [mesh, problem, result] = read_and_solve(
      o, [&o](const qd::io::MeshDocument& m) { return qd::cli::make_problem(m, o); },
      [](const qd::approximate::Problem& p, const qd::common::Progress& progress) {
        return qd::approximate::approximate(p, progress, option_setting);
      });
  std::vector<std::pair<std::string, std::string>> files = {
      {o.output, ply_bytes(qd::io::approximated_document(mesh, result, o.settings))}};
  if (!o.report.empty()) {
    const qd::frontend::ReportContext context{o.input,
                                              o.output,
                                              o.settings,
                                              static_cast<int>(mesh.positions.size()),
                                              static_cast<int>(mesh.triangles.size()),
                                              !mesh.patch.empty(),
                                              count_constrained(problem.constrained),
                                              mesh.notes};
    files.emplace_back(o.report, qd::frontend::report_json(result, context));
  }
  write_files(files);
  print_outcome(o, result.warnings, result.log, mesh.notes);
}

void segment(const qd::cli::SegmentOptions& o) {
  const auto [mesh, problem, result] = read_and_solve(
      o, [&o](const qd::io::MeshDocument& m) { return qd::cli::make_segment_problem(m, o); },
      [](const qd::segment::SegmentProblem& p, const qd::common::Progress& progress) {
        return qd::segment::segment(p, progress);
      });
  std::vector<std::pair<std::string, std::string>> files = {
      {o.output, ply_bytes(qd::io::segmented_document(mesh, result))}};
  if (!o.report.empty()) {
    const qd::frontend::SegmentReportContext context{o.input,
                                                     o.output,
                                                     o.settings,
                                                     static_cast<int>(mesh.positions.size()),
                                                     static_cast<int>(mesh.triangles.size()),
                                                     !mesh.patch.empty(),
                                                     count_constrained(problem.selected),
                                                     mesh.notes};
    files.emplace_back(o.report, qd::frontend::segment_report_json(result, context));
  }
  write_files(files);
  print_outcome(o, result.warnings, result.log, mesh.notes);
}

// The marker of the pattern on fabric of the asked width (gap: the flatten gap, else 1 % of the
// width), with both placements' length and efficiency, the one kept and the unplaced pieces on
// the log.
qd::marker::MarkerChoice marker_of(const qd::params::FlattenSettings& s,
                                   const qd::flatten::Pattern& pattern,
                                   std::vector<std::string>& log) {
  const double gap = s.engine.gap > 0 ? s.engine.gap : 0.01 * s.marker_width;
  qd::marker::MarkerChoice c = qd::marker::cut_marker(pattern, s.marker_width, gap);
  for (const auto& [name, m, kept] : {std::tuple{"nested (libnest2d)", &c.nested, c.nested_kept},
                                      std::tuple{"row by row", &c.rows, !c.nested_kept}}) {
    log.push_back(qd::common::format_text(
        "marker %s: width %g, length %g, efficiency %g %%, %zu pieces, gap %g%s", name,
        s.marker_width, m->length, 100 * m->efficiency, m->placements.size(), gap,
        kept ? " (kept: the shorter)" : ""));
  }
  for (const std::string& label : c.kept().unplaced)
    log.push_back("marker: piece " + label + " is wider than the fabric, not placed");
  return c;
}

void flatten(const qd::cli::FlattenOptions& o) {
  const auto [mesh, problem, result] = read_and_solve(
      o, [&o](const qd::io::MeshDocument& m) { return qd::cli::make_flatten_problem(m, o); },
      [](const qd::flatten::FlattenProblem& p, const qd::common::Progress& progress) {
        return qd::flatten::flatten(p, progress);
      });
  const qd::params::FlattenSettings& s = o.settings;
  std::vector<std::string> log = result.log;
  std::vector<std::pair<std::string, std::string>> files = {
      {o.output, ply_bytes(qd::io::flattened_document(mesh, result))}};
  for (auto& file : qd::io::pattern_files(s, result.pattern)) files.push_back(std::move(file));
  if (!s.pdf_file.empty()) {
    auto pdf = qd::pdf::printable_pdf(result.pattern, s.paper, s.unit);
    files.emplace_back(s.pdf_file, std::move(pdf.bytes));
    log.push_back(pdf.summary);
  }
  std::optional<qd::marker::MarkerChoice> marker;
  if (s.marker_width > 0) {
    marker = marker_of(s, result.pattern, log);
    if (!s.marker_svg_file.empty()) {
      std::ostringstream svg;
      qd::marker::write_marker_svg(svg, marker->kept(), result.pattern);
      files.emplace_back(s.marker_svg_file, svg.str());
    }
    if (!s.marker_dxf_file.empty()) {
      std::ostringstream dxf;
      qd::marker::write_marker_dxf(dxf, marker->kept(), result.pattern);
      files.emplace_back(s.marker_dxf_file, dxf.str());
    }
  }
  if (!o.report.empty()) {
    const qd::frontend::FlattenReportContext context{o.input,
                                                     o.output,
                                                     o.settings,
                                                     static_cast<int>(mesh.positions.size()),
                                                     static_cast<int>(mesh.triangles.size()),
                                                     !mesh.patch.empty(),
                                                     mesh.notes,
                                                     log};
    files.emplace_back(o.report,
                       qd::cli::flatten_report_json(result, context, marker ? &*marker : nullptr));
  }
  write_files(files);
  print_outcome(o, {}, log, mesh.notes);
}

int fail(const std::string& reason, int status) {
  progress_line.close();
  std::string line = reason;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  std::cerr << "quasidev: error: " << line << std::endl;
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  qd::cli::restart_with_fast_blas_kernels(argv);
  std::signal(SIGPIPE, SIG_IGN);  // a closed stdout must not kill the command by a signal
  if (argc > 1 && std::string(argv[1]) == "batch") return qd::cli::run_python_batch(argc, argv);
  try {
    const qd::cli::CommandLine line =
        qd::cli::parse_command_line(std::vector<std::string>(argv + 1, argv + argc));
    if (!line.print.empty()) {
      std::cout << line.print;
      return 0;
    }
    if (line.job == qd::cli::Job::Segment)
      segment(line.segment);
    else if (line.job == qd::cli::Job::Flatten)
      flatten(line.flatten);
    else
      approximate(line.approximate);
    return 0;
  } catch (const qd::cli::UsageError& e) {
    return fail(e.what(), 2);
  } catch (const qd::common::Error& e) {
    return fail(e.what(), 1);
  } catch (const std::bad_alloc&) {
    return fail("out of memory (is the mesh too large for this machine?)", 1);
  } catch (const std::exception& e) {
    return fail(std::string("unexpected failure: ") + e.what(), 1);
  }
}
