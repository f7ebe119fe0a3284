// qd_bench: times the quasi-developable approximation stage by stage on one mesh and prints one
// JSON object: per-stage medians over several runs, peak memory, the bare solver floor and the
// overhead ratios of issue 5. scripts/bench.py runs it over the suite and draws the scaling plot.
//
// Usage: qd_bench (--grid TRIANGLES [--patches P] | --tube TRIANGLES | --mesh FILE) [--save FILE]
//                 [--runs R]
//                 [-- QUASIDEV OPTIONS]
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "approximate/quasidev.h"
#include "bare_solver.h"
#include "bench_mesh.h"
#include "blas_kernels.h"
#include "common/error.h"
#include "io/atomic_file.h"
#include "io/mesh_reader.h"
#include "io/output_mesh.h"
#include "io/result_document.h"
#include "mesh_geometry.h"
#include "mesh_problem.h"
#include "options.h"

namespace {

using namespace qd::approximate;
using namespace qd::common;

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// This program's own peak resident memory (VmHWM): getrusage's ru_maxrss would include the
// peak of the parent that started it (a script holding large meshes), kept across fork and exec.
double peak_rss_mb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  double kb = 0;
  while (status >> key && key != "VmHWM:") status.ignore(1 << 20, '\n');
  status >> kb;
  return kb / 1024.0;
}

struct Args {
  long grid = 0;
  int patches = 1;
  long tube = 0;
  std::string mesh;
  int runs = 5;
  std::string save;                   // keep the generated mesh here
  std::vector<std::string> quasidev;  // options passed to the engine as quasidev would
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    const auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw qd::common::Error(s + " needs a value");
      return argv[++i];
    };
    if (s == "--grid")
      a.grid = std::stol(next());
    else if (s == "--patches")
      a.patches = std::stoi(next());
    else if (s == "--tube")
      a.tube = std::stol(next());
    else if (s == "--mesh")
      a.mesh = next();
    else if (s == "--runs")
      a.runs = std::max(1, std::stoi(next()));
    else if (s == "--save")
      a.save = next();
    else if (s == "--")
      a.quasidev.assign(argv + i + 1, argv + argc), i = argc;
    else
      throw qd::common::Error("unknown argument " + s);
  }
  if (a.grid <= 0 && a.tube <= 0 && a.mesh.empty())
    throw qd::common::Error("give --grid TRIANGLES, --tube TRIANGLES or --mesh FILE");
  return a;
}

// The mesh as the binary PLY the command writes.
std::string serialize(const qd::io::MeshDocument& mesh) {
  qd::io::MeshDocument doc = mesh;
  qd::io::set_positions(doc, qd::cli::positions_of(mesh));
  return qd::io::serialize_ply(doc, qd::io::PlyFormat::BinaryLittleEndian);
}

void run(const Args& a) {
  const std::string scratch = "/tmp/qd_bench_" + std::to_string(getpid());
  const std::string input = !a.mesh.empty()   ? a.mesh
                            : !a.save.empty() ? a.save
                                              : scratch + "_in.ply";
  const std::string output = scratch + "_out.ply";
  if (a.mesh.empty()) {
    qd::io::MeshDocument generated =
        a.tube > 0 ? qd::bench::noisy_tube(a.tube) : qd::bench::curved_sheet(a.grid, a.patches);
    if (!generated.patch.empty())  // patch ids travel as face quality, as MeshLab writes them
      generated.face_extra.push_back(qd::io::scalar_property(
          "quality", qd::io::ScalarType::Float32,
          std::vector<double>(generated.patch.begin(), generated.patch.end())));
    qd::io::PendingFile file(input, serialize(generated));
    file.commit();
  }
  std::vector<std::string> args = {input, output};
  args.insert(args.end(), a.quasidev.begin(), a.quasidev.end());
  const qd::cli::ApproximateOptions options = qd::cli::parse_command_line(args).approximate;

  std::vector<double> read_ms, write_ms, wall_ms, setup, step1, assembly, factor, solve, metrics;
  qd::approximate::Result result;
  qd::io::MeshDocument mesh;
  long progress_calls = 0;  // per run: the callback must stay rare (issue 5, bullet 4)
  for (int r = 0; r < a.runs; ++r) {
    auto t0 = Clock::now();
    mesh = qd::io::read_mesh(input);
    const qd::approximate::Problem problem = qd::cli::make_problem(mesh, options);
    read_ms.push_back(ms_since(t0));

    t0 = Clock::now();
    progress_calls = 0;
    result =
        qd::approximate::approximate(problem, [&](int, const std::string&) { ++progress_calls; });
    wall_ms.push_back(ms_since(t0));
    setup.push_back(result.times.setup);
    step1.push_back(result.times.step1);
    assembly.push_back(result.times.assembly);
    factor.push_back(result.times.factorization);
    solve.push_back(result.times.solve);
    metrics.push_back(result.times.metrics);

    t0 = Clock::now();
    qd::io::PendingFile file(
        output, qd::io::serialize_ply(qd::io::approximated_document(mesh, result, options.settings),
                                      qd::io::PlyFormat::BinaryLittleEndian));
    file.commit();
    write_ms.push_back(ms_since(t0));
  }
  const double peak_mb = peak_rss_mb();

  const qd::approximate::Problem problem = qd::cli::make_problem(mesh, options);
  const std::vector<qd::bench::BareGroup> bare = qd::bench::bare_solver_times(problem, a.runs);
  // The floor: per group, the factorisations and solves the method needs (one factorisation
  // with fixed targets, one per solve when the targets change, all but the first reusing the
  // analysis) at the bare solver's speed.
  double bare_factor = 0, bare_refactor = 0, floor = 0, bare_solve_sum = 0;
  long unknowns = 0;
  const bool fixed_targets = options.settings.engine.targets == qd::approximate::TargetMode::Fixed;
  for (const auto& g : bare) {
    bare_factor += g.factor_ms;
    bare_refactor += g.refactor_ms;
    bare_solve_sum += g.solve_ms;
    unknowns = std::max(unknowns, g.unknowns);
    for (const qd::approximate::PatchReport& p : result.patches) {
      if (p.id != g.patch && g.patch >= 0) continue;
      const bool refused =
          !p.stops.empty() && p.stops.back().reason == qd::approximate::PatchStop::NoStep;
      const int solves = p.iterations + (refused ? 1 : 0);  // the refused step was solved too
      const int refactorizations = fixed_targets ? 0 : std::max(0, solves - 1);
      floor += g.factor_ms + refactorizations * g.refactor_ms + solves * g.solve_ms;
      if (g.patch < 0) break;  // one joint group: count it once
    }
  }
  const int solves = std::max(1, result.times.solves);
  const double engine = median(wall_ms), io = median(read_ms) + median(write_ms);
  const double per_iteration_solve = median(solve) / solves;
  const double mean_bare_solve =
      bare.empty() ? 0 : bare_solve_sum / static_cast<double>(bare.size());

  std::printf(
      "{\"mesh\": \"%s\", \"faces\": %ld, \"vertices\": %ld, \"patches\": %zu, \"runs\": %d, "
      "\"iterations\": %d, \"solves\": %d, \"factorizations\": %d, "
      "\"factorization_gflop\": %.4f, \"solve_gb\": %.4f, \"cg_iterations\": %d, "
      "\"largest_unknowns\": %ld, "
      "\"ms\": {\"read\": %.3f, \"setup\": %.3f, \"step1\": %.3f, \"assembly\": %.3f, "
      "\"factorization\": %.3f, "
      "\"solve\": %.3f, \"metrics\": %.3f, \"engine\": %.3f, \"write\": %.3f, \"end_to_end\": "
      "%.3f}, "
      "\"bare_ms\": {\"factorization\": %.3f, \"refactorization\": %.3f, \"solve\": %.3f, "
      "\"floor\": %.3f}, "
      "\"overhead\": %.3f, \"solve_ratio\": %.3f, \"peak_mb\": %.1f, "
      "\"abd_reduction\": %.2f, \"progress_calls\": %ld}\n",
      !a.mesh.empty() ? a.mesh.c_str()
      : a.tube > 0    ? ("tube" + std::to_string(a.tube)).c_str()
                      : ("grid" + std::to_string(a.grid) + "x" + std::to_string(a.patches)).c_str(),
      static_cast<long>(mesh.triangles.size()), static_cast<long>(mesh.positions.size()),
      result.patches.size(), a.runs,
      [&] {
        int it = 0;
        for (const auto& p : result.patches) it = std::max(it, p.iterations);
        return it;
      }(),
      result.times.solves, result.times.factorizations, result.times.factorization_flops / 1e9,
      result.times.solve_bytes / 1e9, result.times.cg_iterations, unknowns, median(read_ms),
      median(setup), median(step1), median(assembly), median(factor), median(solve),
      median(metrics), engine, median(write_ms), engine + io, bare_factor, bare_refactor,
      mean_bare_solve, floor, engine / std::max(1e-9, floor),
      mean_bare_solve > 0 ? per_iteration_solve / mean_bare_solve : 0.0, peak_mb,
      result.abd_reduction, progress_calls);
  std::remove(output.c_str());
  if (a.mesh.empty() && a.save.empty()) std::remove(input.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  qd::cli::restart_with_fast_blas_kernels(argv);  // the kernels the command runs on
  try {
    run(parse(argc, argv));
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "qd_bench: " << e.what() << '\n';
    return 1;
  }
}
