// quasidev [approximate]: reads a mesh, runs the quasi-developable approximation (qd::approximate),
// writes the deformed mesh as PLY with per-vertex quality and a colour ramp, and optionally a JSON
// report. quasidev segment: reads a mesh, splits it into nearly developable patches
// (qd::segment), writes it as PLY with per-face quality = patch id and a colour per patch, and
// optionally a JSON report. Subcommands and options: options.h.
// Exit 0 on success; 1 on bad input or an engine error; 2 on a bad command line. On error one
// line "quasidev: error: REASON" goes to stderr and no OUTPUT (or report) file is written.
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>

#include "approximate/quasidev.h"
#include "atomic_file.h"
#include "mesh_problem.h"
#include "mesh_reader.h"
#include "options.h"
#include "output_mesh.h"
#include "ply_writer.h"
#include "report_json.h"
#include "segment/segment.h"
#include "segment_mesh.h"
#include "segment_report_json.h"

namespace {

using qd::cli::Options;

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

// Refuses to replace the input (unless asked) or to write the report over the mesh.
template <typename JobOptions>
void check_paths(const JobOptions& o) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!o.overwrite_input && fs::exists(o.output, ec) && fs::equivalent(o.input, o.output, ec))
    throw qd::cli::UsageError("OUTPUT is the INPUT file; pass --overwrite-input to replace it");
  if (!o.report.empty() && fs::exists(o.report, ec) &&
      (fs::equivalent(o.report, o.input, ec) || fs::equivalent(o.report, o.output, ec)))
    throw qd::cli::UsageError("the --report file must differ from INPUT and OUTPUT");
}

int count_constrained(const std::vector<char>& constrained) {
  int n = 0;
  for (char c : constrained) n += c ? 1 : 0;
  return n;
}

template <typename JobOptions>
void start_progress(const JobOptions& o) {
  if (o.progress == qd::cli::ProgressMode::On ||
      (o.progress == qd::cli::ProgressMode::Auto && !o.quiet && isatty(STDERR_FILENO)))
    progress_line.enable();
}

const qd::Progress show_progress = [](int percent, const std::string& message) {
  progress_line.show(percent, message);
};

std::string ply_bytes(const qd::meshio::MeshFile& mesh, const qd::meshio::OutputFields& fields) {
  return qd::meshio::serialize_ply(qd::meshio::output_ply(mesh, fields),
                                   qd::meshio::PlyFormat::BinaryLittleEndian);
}

// Writes OUTPUT and, when asked, the report (both staged before either is renamed into place),
// then the warnings on stderr (even with --quiet, like errors: part of the mesh was handled
// specially) and, unless --quiet, the log on stdout and the reader's notes on stderr.
template <typename JobOptions>
void finish(const JobOptions& o, const std::string& ply, const std::string& report_text,
            const std::vector<std::string>& warnings, const std::vector<std::string>& log,
            const std::vector<std::string>& notes) {
  qd::meshio::PendingFile output(o.output, ply);
  std::unique_ptr<qd::meshio::PendingFile> report;
  if (!o.report.empty()) report = std::make_unique<qd::meshio::PendingFile>(o.report, report_text);
  output.commit();
  if (report) report->commit();
  for (const std::string& warning : warnings) std::cerr << "quasidev: warning: " << warning << '\n';
  if (o.quiet) return;
  for (const std::string& line : log) std::cout << line << '\n';
  for (const std::string& note : notes) std::cerr << "quasidev: note: " << note << '\n';
}

void approximate(const Options& o) {
  check_paths(o);
  const qd::meshio::MeshFile mesh = qd::meshio::read_mesh(o.input);
  const qd::Problem problem = qd::cli::make_problem(mesh, o);
  start_progress(o);
  const qd::Result result = qd::approximate(problem, show_progress);
  progress_line.close();
  std::string report;
  if (!o.report.empty()) {
    const qd::cli::ReportContext context{o,
                                         problem.params,
                                         static_cast<int>(mesh.positions.size()),
                                         static_cast<int>(mesh.triangles.size()),
                                         !mesh.patch.empty(),
                                         count_constrained(problem.constrained),
                                         mesh.notes};
    report = report_json(result, context);
  }
  finish(o, ply_bytes(mesh, qd::cli::output_fields(result, o, mesh.positions.size())), report,
         result.warnings, result.log, mesh.notes);
}

void segment(const qd::cli::SegmentOptions& o) {
  check_paths(o);
  const qd::meshio::MeshFile mesh = qd::meshio::read_mesh(o.input);
  const qd::SegmentProblem problem = qd::cli::make_segment_problem(mesh, o);
  start_progress(o);
  const qd::SegmentResult result = qd::segment(problem, show_progress);
  progress_line.close();
  std::string report;
  if (!o.report.empty()) {
    const qd::cli::SegmentReportContext context{o,
                                                static_cast<int>(mesh.positions.size()),
                                                static_cast<int>(mesh.triangles.size()),
                                                !mesh.patch.empty(),
                                                count_constrained(problem.selected),
                                                mesh.notes};
    report = segment_report_json(result, context);
  }
  // The segmentation's log opens with its warnings (segment_log.h), which go to stderr here.
  const std::vector<std::string> log(result.log.begin() + static_cast<long>(result.warnings.size()),
                                     result.log.end());
  finish(o, ply_bytes(mesh, qd::cli::segment_output_fields(result, mesh)), report, result.warnings,
         log, mesh.notes);
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
  std::signal(SIGPIPE, SIG_IGN);  // a closed stdout must not kill the command by a signal
  try {
    const qd::cli::CommandLine line =
        qd::cli::parse_command_line(std::vector<std::string>(argv + 1, argv + argc));
    if (!line.print.empty()) {
      std::cout << line.print;
      return 0;
    }
    if (line.job == qd::cli::Job::Segment)
      segment(line.segment);
    else
      approximate(line.approximate);
    return 0;
  } catch (const qd::cli::UsageError& e) {
    return fail(e.what(), 2);
  } catch (const qd::Error& e) {
    return fail(e.what(), 1);
  } catch (const std::bad_alloc&) {
    return fail("out of memory (is the mesh too large for this machine?)", 1);
  } catch (const std::exception& e) {
    return fail(std::string("unexpected failure: ") + e.what(), 1);
  }
}
