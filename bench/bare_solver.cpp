#include "bare_solver.h"

#include <algorithm>
#include <chrono>
#include <map>

#include "approximate/deformation_system.h"
#include "approximate/group_mesh.h"
#include "approximate/target_normals.h"
#include "approximate/validate.h"
#include "common/error.h"
#include "common/mesh.h"
#include "common/metrics.h"
#include "common/positive_definite_factor.h"

namespace qd::bench {
namespace {

using namespace qd::approximate;
using namespace qd::common;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

template <typename F>
double time_ms(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

std::vector<BareGroup> bare_solver_times(const Problem& problem, int runs) {
  const Topology topo = validate(problem);
  const Params& params = problem.params;
  const size_t nf = static_cast<size_t>(problem.F.rows());
  const std::vector<int> patch = problem.patch.empty() ? std::vector<int>(nf, 0) : problem.patch;
  const VertexRoles roles = vertex_roles(problem, topo, problem.params.seams);
  std::map<int, std::vector<int>> groups;
  for (size_t f = 0; f < nf; ++f)
    groups[params.seams == SeamMode::Fixed ? patch[f] : -1].push_back(static_cast<int>(f));
  const VertexFaces incident(problem.F, problem.V.rows());
  const double ae = average_edge_length(problem.V, problem.F);

  std::vector<BareGroup> out;
  for (const auto& [id, faces] : groups) {
    const GroupMesh g = extract_group(problem.V, problem.F, faces, patch, roles.constrained,
                                      roles.interior, incident, params);
    std::vector<Vec3> normals;
    std::vector<double> areas;
    for (Eigen::Index f = 0; f < g.solve_faces; ++f) {
      normals.push_back(face_normal(g.V0, g.F, static_cast<int>(f)));
      areas.push_back(face_area(g.V0, g.F, static_cast<int>(f)));
    }
    Params direct = params;  // the floor is the coupled factorisation
    direct.method = SolveMethod::Direct;
    DeformationSystem system(g, direct, ae);
    try {
      system.set_rows(fit_targets(normals, areas).targets);
    } catch (const Error&) {  // no curve fits: the engine keeps the face normals, so do we
      system.set_rows(normals);
    }
    const Eigen::VectorXd b = system.rhs(g.V0);
    BareGroup bare;
    bare.patch = id;
    bare.unknowns = system.matrix().rows();
    if (bare.unknowns == 0) continue;
    std::vector<double> factor, refactor, solve;
    for (int r = 0; r < runs; ++r) {
      PositiveDefiniteFactor cholesky(params.solver);
      factor.push_back(time_ms([&] { cholesky.factorize(system.matrix()); }));
      refactor.push_back(time_ms([&] { cholesky.factorize(system.matrix()); }));
      Eigen::VectorXd x;
      solve.push_back(time_ms([&] { x = cholesky.solve(b); }));
    }
    bare.factor_ms = median(factor);
    bare.refactor_ms = median(refactor);
    bare.solve_ms = median(solve);
    out.push_back(bare);
  }
  return out;
}

}  // namespace qd::bench
