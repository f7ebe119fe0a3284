// qd_flatten_bench: flattens one mesh (core/flatten) and prints one JSON object: the time, the
// pieces' figures and, against ground truth, the largest relative edge-length error of the
// pattern — against the 3D edges always, and against the file's own flat pattern (per-corner
// `texcoord`) when it has one (developable_crumpled_crane.ply: its exact flattening).
//
// Usage: qd_flatten_bench (--grid TRIANGLES [--patches P] | --mesh FILE) [--runs R]
//                         [--threads T] [--arap-max-iter N] [--arap-tolerance X]
//                         [--svg-file FILE] [--dxf-file FILE] [--unit U]
// (the flattening's parameters by their declared names: docs/reference/flatten.md)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "bench_mesh.h"
#include "common/error.h"
#include "flatten/flatten.h"
#include "io/dxf_writer.h"
#include "io/mesh_reader.h"
#include "io/svg_writer.h"
#include "mesh_geometry.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

struct Args {
  long grid = 0;
  int patches = 1;
  std::string mesh, svg, dxf, unit;
  int runs = 1;
  qd::flatten::FlattenParams params;
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--grid")
      a.grid = std::stol(value);
    else if (key == "--patches")
      a.patches = std::stoi(value);
    else if (key == "--mesh")
      a.mesh = value;
    else if (key == "--runs")
      a.runs = std::stoi(value);
    else if (key == "--threads")
      a.params.threads = std::stoi(value);
    else if (key == "--arap-max-iter")
      a.params.max_iterations = std::stoi(value);
    else if (key == "--arap-tolerance")
      a.params.tolerance = std::stod(value);
    else if (key == "--svg-file")
      a.svg = value;
    else if (key == "--dxf-file")
      a.dxf = value;
    else if (key == "--unit")
      a.unit = value;
    else
      throw qd::common::Error("unknown option " + key);
  }
  if ((a.grid > 0) == !a.mesh.empty())
    throw qd::common::Error("give --grid TRIANGLES or --mesh FILE");
  return a;
}

qd::flatten::FlattenProblem problem_of(const qd::io::MeshDocument& mesh) {
  qd::flatten::FlattenProblem p;
  qd::cli::set_geometry(mesh, p);
  return p;
}

// Largest |l_pattern − l_reference| / l_reference over every face edge; `reference` per face
// corner (u, v) or, when empty, the 3D edges.
double max_edge_error(const qd::flatten::FlattenProblem& p, const qd::flatten::WedgeUV& uv,
                      const qd::flatten::WedgeUV& reference) {
  double worst = 0;
  for (int f = 0; f < p.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int l = (k + 1) % 3;
      const double ours = (uv.block<1, 2>(f, 2 * k) - uv.block<1, 2>(f, 2 * l)).norm();
      const double ref =
          reference.rows() > 0
              ? (reference.block<1, 2>(f, 2 * k) - reference.block<1, 2>(f, 2 * l)).norm()
              : (p.V.row(p.F(f, k)) - p.V.row(p.F(f, l))).norm();
      worst = std::max(worst, std::abs(ours - ref) / ref);
    }
  return worst;
}

// The file's per-corner texcoord, or an empty matrix.
qd::flatten::WedgeUV file_texcoords(const qd::io::MeshDocument& mesh) {
  for (const qd::io::PlyProperty& prop : mesh.face_extra) {
    if (prop.name != "texcoord" || !prop.is_list) continue;
    qd::flatten::WedgeUV uv(static_cast<Eigen::Index>(mesh.triangles.size()), 6);
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
      if (prop.list_size(f) != 6) return {};
      for (int k = 0; k < 6; ++k)
        uv(static_cast<Eigen::Index>(f), k) = prop.values[prop.offsets[f] + static_cast<size_t>(k)];
    }
    return uv;
  }
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Args a = parse(argc, argv);
    const qd::io::MeshDocument mesh =
        a.grid > 0 ? qd::bench::curved_sheet(a.grid, a.patches) : qd::io::read_mesh(a.mesh);
    qd::flatten::FlattenProblem problem = problem_of(mesh);
    problem.params = a.params;
    std::vector<double> ms;
    qd::flatten::FlattenResult r;
    for (int run = 0; run < a.runs; ++run) {
      const auto t0 = std::chrono::steady_clock::now();
      r = qd::flatten::flatten(problem);
      ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(ms.begin(), ms.end());
    const qd::flatten::WedgeUV truth = file_texcoords(mesh);
    std::printf(
        "{\"triangles\": %ld, \"pieces\": %zu, \"median_ms\": %.1f, \"max_edge_error_vs_3d\": %.3e",
        static_cast<long>(problem.F.rows()), r.pieces.size(), ms[ms.size() / 2],
        max_edge_error(problem, r.uv, {}));
    if (truth.rows() > 0)
      std::printf(", \"max_edge_error_vs_texcoord\": %.3e, \"texcoord_edge_error_vs_3d\": %.3e",
                  max_edge_error(problem, r.uv, truth), max_edge_error(problem, truth, {}));
    std::printf(", \"log\": [\n");
    for (size_t i = 0; i < r.log.size(); ++i)
      std::printf("  \"%s\"%s\n", r.log[i].c_str(), i + 1 < r.log.size() ? "," : "");
    std::printf("]}\n");
    if (!a.svg.empty()) {
      std::ofstream out(a.svg);
      qd::io::write_svg(out, r.pattern, a.unit);
    }
    if (!a.dxf.empty()) {
      std::ofstream out(a.dxf);
      qd::io::write_dxf(out, r.pattern, a.unit);
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "qd_flatten_bench: " << e.what() << "\n";
    return 1;
  }
}
