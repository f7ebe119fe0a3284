// qd_segment_bench: times the segmentation (core/segment) and prints one JSON object per mesh:
// faces, patches, disks, patches over the limit and the largest fit error, growing rounds, the
// median wall time over the runs for each thread count, whether every thread count gave the
// same patches, and peak memory. With --approximate it then runs the approximation with the
// command's defaults (or the quasidev options after --) on the patches found and adds its
// G_ABD reduction and largest move.
//
// Usage: qd_segment_bench (--torus TRIANGLES | --mesh FILE)... [--runs R] [--threads T,...]
//                         [--max-error-deg X] [--min-faces N] [--crease-deg X]
//                         [--target-patches K] [--approximate [-- QUASIDEV OPTIONS]]
// (the segmentation's parameters by their declared names: docs/reference/segment.md)
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "approximate/quasidev.h"
#include "bench_mesh.h"
#include "common/error.h"
#include "common/format_text.h"
#include "io/mesh_reader.h"
#include "mesh_geometry.h"
#include "mesh_problem.h"
#include "options.h"
#include "segment/segment.h"

namespace {

using namespace qd::approximate;
using namespace qd::common;
using namespace qd::segment;

struct Args {
  std::vector<std::string> meshes;  // "torus:N" or a path
  int runs = 3;
  std::vector<int> threads = {1, 2};
  qd::segment::SegmentParams params;
  bool approximate = false;
  std::vector<std::string> quasidev = {"in.ply", "out.ply"};  // options for --approximate
};

std::vector<int> int_list(const std::string& text) {
  std::vector<int> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) out.push_back(std::stoi(item));
  return out;
}

// The options that take a value, and what each sets.
using Setter = std::function<void(Args&, const std::string&)>;
const std::map<std::string, Setter> kValueOptions = {
    {"--torus", [](Args& a, const std::string& v) { a.meshes.push_back("torus:" + v); }},
    {"--mesh", [](Args& a, const std::string& v) { a.meshes.push_back(v); }},
    {"--runs", [](Args& a, const std::string& v) { a.runs = std::max(1, std::stoi(v)); }},
    {"--threads", [](Args& a, const std::string& v) { a.threads = int_list(v); }},
    {"--max-error-deg",
     [](Args& a, const std::string& v) { a.params.max_error_deg = std::stod(v); }},
    {"--min-faces", [](Args& a, const std::string& v) { a.params.min_faces = std::stoi(v); }},
    {"--crease-deg", [](Args& a, const std::string& v) { a.params.crease_deg = std::stod(v); }},
    {"--target-patches",
     [](Args& a, const std::string& v) { a.params.target_patches = std::stoi(v); }},
};

Args parse(int argc, char** argv) {
  Args a;
  const std::vector<std::string> args(argv + 1, argv + argc);
  for (auto it = args.begin(); it != args.end(); ++it) {
    const auto option = kValueOptions.find(*it);
    if (option != kValueOptions.end()) {
      if (std::next(it) == args.end()) throw qd::common::Error(*it + " needs a value");
      option->second(a, *++it);
    } else if (*it == "--approximate") {
      a.approximate = true;
    } else if (*it == "--") {
      a.quasidev.insert(a.quasidev.end(), std::next(it), args.end());
      break;
    } else {
      throw qd::common::Error("unknown argument " + *it);
    }
  }
  if (a.meshes.empty()) throw qd::common::Error("give --torus TRIANGLES or --mesh FILE");
  if (a.threads.empty()) throw qd::common::Error("--threads needs a list such as 1,2");
  return a;
}

qd::io::MeshDocument load(const std::string& name) {
  if (name.rfind("torus:", 0) == 0) return qd::bench::torus(std::stol(name.substr(6)));
  return qd::io::read_mesh(name);
}

qd::segment::SegmentProblem segment_problem(const qd::io::MeshDocument& mesh,
                                            const qd::segment::SegmentParams& q) {
  qd::segment::SegmentProblem p;
  qd::cli::set_geometry(mesh, p);
  p.params = q;
  return p;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The approximation with the command's defaults on the segmented mesh: G_ABD reduction in
// percent and the largest vertex move in average edge lengths.
std::string approximate(const qd::io::MeshDocument& mesh, const std::vector<int>& patch,
                        const std::vector<std::string>& quasidev) {
  qd::io::MeshDocument segmented = mesh;
  segmented.patch = patch;
  const qd::cli::ApproximateOptions options = qd::cli::parse_command_line(quasidev).approximate;
  const qd::approximate::Result r =
      qd::approximate::approximate(qd::cli::make_problem(segmented, options));
  return qd::common::format_text(", \"abd_reduction\": %.2f, \"max_move_ae\": %.3f",
                                 r.abd_reduction, r.total_after.max_disp / r.average_edge);
}

void run(const Args& a, const std::string& name) {
  const qd::io::MeshDocument mesh = load(name);
  qd::segment::SegmentProblem problem = segment_problem(mesh, a.params);
  std::string times;
  qd::segment::SegmentResult first;
  bool same = true;
  for (const int threads : a.threads) {
    problem.params.threads = threads;
    std::vector<double> ms;
    for (int r = 0; r < a.runs; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      qd::segment::SegmentResult result = qd::segment::segment(problem);
      ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      if (first.patch.empty())
        first = std::move(result);
      else
        same = same && result.patch == first.patch;
    }
    times += (times.empty() ? "" : ", ") + ("\"" + std::to_string(threads) + "\": ") +
             std::to_string(median(ms));
  }
  int disks = 0, over = 0;
  double worst = 0;
  for (const qd::segment::SegmentPatch& s : first.patches) {
    disks += s.disk;
    over += s.over_limit != qd::segment::OverLimit::No;
    worst = std::max(worst, s.max_error_deg);
  }
  std::printf(
      "{\"mesh\": \"%s\", \"faces\": %zu, \"max_error_limit\": %g, \"min_faces\": %d, "
      "\"patches\": %zu, \"disks\": %d, \"over_limit\": %d, \"max_error_deg\": %.3f, "
      "\"rounds\": %d, \"ms_by_threads\": {%s}, \"same_for_all_threads\": %s, "
      "\"peak_mb\": %.1f%s}\n",
      name.c_str(), mesh.triangles.size(), a.params.max_error_deg, a.params.min_faces,
      first.patches.size(), disks, over, worst, first.rounds, times.c_str(),
      same ? "true" : "false", peak_rss_mb(),
      a.approximate ? approximate(mesh, first.patch, a.quasidev).c_str() : "");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Args a = parse(argc, argv);
    for (const std::string& name : a.meshes) run(a, name);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "qd_segment_bench: " << e.what() << '\n';
    return 1;
  }
}
