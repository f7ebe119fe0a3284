#include "approximate/patch_figures.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>
#include <unordered_set>

#include "approximate/common_names.h"
#include "common/parallel_for.h"

namespace qd::approximate {
namespace {

std::vector<int> indices(size_t n) {
  std::vector<int> v(n);
  std::iota(v.begin(), v.end(), 0);
  return v;
}

double reduction(double before, double after) {
  return before > 0 ? 100.0 * (before - after) / before : 0.0;
}

}  // namespace

void measure_result(Result& r, std::map<int, PatchReport>& reports, const Positions& V0,
                    const Triangles& F, const std::vector<int>& patch,
                    const std::vector<Vec3>& initial_target, const std::vector<char>& interior,
                    const std::vector<char>& constrained, size_t threads) {
  const size_t nv = static_cast<size_t>(V0.rows()), nf = static_cast<size_t>(F.rows());
  assert(static_cast<size_t>(r.V.rows()) == nv && patch.size() == nf &&
         initial_target.size() == nf && interior.size() == nv && constrained.size() == nv);
  const VertexAngles angles_before = vertex_angles(V0, F);
  const VertexAngles angles_after = vertex_angles(r.V, F);
  std::map<int, std::vector<int>> faces_of_patch;
  for (size_t f = 0; f < nf; ++f) faces_of_patch[patch[f]].push_back(static_cast<int>(f));
  std::vector<int> ids;
  for (const auto& entry : faces_of_patch) ids.push_back(entry.first);
  parallel_for(ids.size(), threads, [&](size_t k) {
    const int id = ids[k];
    const std::vector<int>& faces = faces_of_patch.at(id);
    std::vector<int> vertices, owned;  // in the order the faces reach them
    std::unordered_set<int> seen;      // not a flag per mesh vertex: patches × vertices
    seen.reserve(3 * faces.size());
    for (int f : faces)
      for (int c = 0; c < 3; ++c) {
        const auto v = static_cast<size_t>(F(f, c));
        if (!seen.insert(static_cast<int>(v)).second) continue;
        vertices.push_back(static_cast<int>(v));
        if (interior[v]) owned.push_back(static_cast<int>(v));
      }
    std::vector<Vec3> t;
    for (int f : faces) t.push_back(initial_target[static_cast<size_t>(f)]);
    PatchReport& rep = reports.at(id);  // the map is not resized here: safe in parallel
    rep.faces = static_cast<int>(faces.size());
    rep.vertices = static_cast<int>(vertices.size());
    rep.free_vertices =
        static_cast<int>(std::count_if(vertices.begin(), vertices.end(), [&](int v) {
          return !constrained[static_cast<size_t>(v)];
        }));
    rep.before = measure(angles_before, V0, V0, F, owned, faces, t, vertices);
    rep.after = measure(angles_after, V0, r.V, F, owned, faces, t, vertices);
    rep.abd_reduction = reduction(rep.before.g_abd, rep.after.g_abd);
    rep.obd_reduction = reduction(rep.before.obd, rep.after.obd);
  });

  std::vector<int> interior_list;
  for (size_t v = 0; v < nv; ++v)
    if (interior[v]) interior_list.push_back(static_cast<int>(v));
  const std::vector<int> all_faces = indices(nf), all_vertices = indices(nv);
  r.k_after = gaussian_curvature(angles_after, interior);
  r.displacement.resize(nv);
  for (size_t v = 0; v < nv; ++v)
    r.displacement[v] =
        (r.V.row(static_cast<Eigen::Index>(v)) - V0.row(static_cast<Eigen::Index>(v))).norm();
  r.total_before =
      measure(angles_before, V0, V0, F, interior_list, all_faces, initial_target, all_vertices);
  r.total_after =
      measure(angles_after, V0, r.V, F, interior_list, all_faces, initial_target, all_vertices);
  r.abd_reduction = reduction(r.total_before.g_abd, r.total_after.g_abd);
}

}  // namespace qd::approximate

namespace qd::approximate {

double held_curvature_share(const std::vector<double>& k, const std::vector<char>& interior,
                            const std::vector<char>& constrained) {
  double on_held = 0, all = 0;
  for (size_t v = 0; v < k.size(); ++v) {
    all += std::abs(k[v]);
    if (interior[v] && constrained[v]) on_held += std::abs(k[v]);
  }
  return all > 0 ? 100.0 * on_held / all : 0.0;
}

}  // namespace qd::approximate
