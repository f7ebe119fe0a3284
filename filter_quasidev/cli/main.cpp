// quasidev: reads a mesh, runs the quasi-developable approximation (qd::approximate), writes the
// deformed mesh as PLY with per-vertex quality and a colour ramp, and optionally a JSON report.
// Exit 0 on success; 1 on bad input or an engine error; 2 on a bad command line. On error one
// line "quasidev: error: REASON" goes to stderr and no OUTPUT (or report) file is written.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>

#include "atomic_file.h"
#include "constraint_file.h"
#include "mesh_reader.h"
#include "options.h"
#include "output_mesh.h"
#include "ply_writer.h"
#include "quality_range.h"
#include "quasidev.h"
#include "report_json.h"

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
void check_paths(const Options& o) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!o.overwrite_input && fs::exists(o.output, ec) && fs::equivalent(o.input, o.output, ec))
    throw qd::cli::UsageError("OUTPUT is the INPUT file; pass --overwrite-input to replace it");
  if (!o.report.empty() && fs::exists(o.report, ec) &&
      (fs::equivalent(o.report, o.input, ec) || fs::equivalent(o.report, o.output, ec)))
    throw qd::cli::UsageError("the --report file must differ from INPUT and OUTPUT");
}

qd::Problem make_problem(const qd::meshio::MeshFile& mesh, const Options& o) {
  qd::Problem problem;
  problem.V.resize(static_cast<Eigen::Index>(mesh.positions.size()), 3);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    for (int k = 0; k < 3; ++k)
      problem.V(static_cast<Eigen::Index>(i), k) = mesh.positions[i][static_cast<std::size_t>(k)];
  problem.F.resize(static_cast<Eigen::Index>(mesh.triangles.size()), 3);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k)
      problem.F(static_cast<Eigen::Index>(f), k) = mesh.triangles[f][static_cast<std::size_t>(k)];
  problem.patch = mesh.patch;
  problem.constrained = mesh.constrained;
  if (!o.constraints.empty()) {
    problem.constrained.resize(mesh.positions.size(), 0);
    for (std::size_t v : qd::meshio::read_constraint_file(o.constraints, mesh.positions.size()))
      problem.constrained[v] = 1;
  }
  const double ae = qd::average_edge_length(problem.V, problem.F);
  if (!(ae > 0) || !std::isfinite(ae))
    throw qd::Error("the mesh's average edge length is " + std::to_string(ae) +
                    " (all vertices coincide?); nothing to approximate");
  problem.params = o.params;
  problem.params.tolerance = o.tolerance_ae * ae;
  for (const auto& [id, x] : o.patch_tolerance_ae) {
    if (std::find(mesh.patch.begin(), mesh.patch.end(), id) == mesh.patch.end() &&
        !(mesh.patch.empty() && id == 0))
      throw qd::cli::UsageError("--patch-tolerance names patch " + std::to_string(id) +
                                ", which the mesh does not have");
    problem.params.patch_tolerance[id] = x * ae;
  }
  return problem;
}

qd::meshio::OutputFields output_fields(const qd::Result& result, const Options& o,
                                       std::size_t vertex_count) {
  const std::vector<double>& q =
      o.quality == qd::cli::QualityKind::Curvature ? result.k_after : result.displacement;
  if (static_cast<std::size_t>(result.V.rows()) != vertex_count || q.size() != vertex_count)
    throw qd::Error("internal error: the engine returned " + std::to_string(result.V.rows()) +
                    " positions and " + std::to_string(q.size()) + " quality values for " +
                    std::to_string(vertex_count) + " vertices");
  qd::meshio::OutputFields fields;
  fields.positions.resize(vertex_count);
  for (std::size_t i = 0; i < vertex_count; ++i)
    for (int k = 0; k < 3; ++k)
      fields.positions[i][static_cast<std::size_t>(k)] = result.V(static_cast<Eigen::Index>(i), k);
  fields.quality = q;
  if (o.color) {
    const qd::QualityRange range = qd::robust_quality_range(q);
    fields.colors.reserve(vertex_count);
    for (double value : q) fields.colors.push_back(qd::ramp_color(value, range));
  }
  return fields;
}

int count_constrained(const std::vector<char>& constrained) {
  int n = 0;
  for (char c : constrained) n += c ? 1 : 0;
  return n;
}

void run(const Options& o) {
  check_paths(o);
  const qd::meshio::MeshFile mesh = qd::meshio::read_mesh(o.input);
  const qd::Problem problem = make_problem(mesh, o);
  if (o.progress == qd::cli::ProgressMode::On ||
      (o.progress == qd::cli::ProgressMode::Auto && !o.quiet && isatty(STDERR_FILENO)))
    progress_line.enable();
  const qd::Result result = qd::approximate(
      problem, [](int percent, const std::string& message) { progress_line.show(percent, message); });
  progress_line.close();
  const qd::meshio::OutputFields fields = output_fields(result, o, mesh.positions.size());
  const std::string ply = qd::meshio::serialize_ply(qd::meshio::output_ply(mesh, fields),
                                                    qd::meshio::PlyFormat::BinaryLittleEndian);
  qd::meshio::PendingFile output(o.output, ply);
  std::unique_ptr<qd::meshio::PendingFile> report;
  if (!o.report.empty()) {
    const qd::cli::ReportContext context{o,
                                         problem.params,
                                         static_cast<int>(mesh.positions.size()),
                                         static_cast<int>(mesh.triangles.size()),
                                         !mesh.patch.empty(),
                                         count_constrained(problem.constrained)};
    report = std::make_unique<qd::meshio::PendingFile>(o.report, report_json(result, context));
  }
  output.commit();
  if (report) report->commit();
  if (o.quiet) return;
  for (const std::string& line : result.log) std::cout << line << '\n';
  for (const std::string& note : mesh.notes) std::cerr << "quasidev: note: " << note << '\n';
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
  try {
    const Options o = qd::cli::parse_options(std::vector<std::string>(argv + 1, argv + argc));
    if (o.help) {
      std::cout << qd::cli::help_text();
      return 0;
    }
    if (o.version) {
      std::cout << "quasidev " << QD_VERSION << '\n';
      return 0;
    }
    run(o);
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
