#include "approximate/group_mesh.h"

#include <algorithm>
#include <cassert>
#include <limits>

namespace qd::approximate {

VertexFaces::VertexFaces(const Triangles& F, Eigen::Index vertex_count)
    : start(static_cast<size_t>(vertex_count) + 1, 0), faces(static_cast<size_t>(F.size())) {
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int c = 0; c < 3; ++c) ++start[static_cast<size_t>(F(f, c)) + 1];
  for (size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<int> next(start.begin(), start.end() - 1);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int c = 0; c < 3; ++c)
      faces[static_cast<size_t>(next[static_cast<size_t>(F(f, c))]++)] = static_cast<int>(f);
}

VertexRoles vertex_roles(const Problem& problem, const Topology& topo, SeamMode seams) {
  const Params& params = problem.params;
  const size_t n = static_cast<size_t>(problem.V.rows());
  VertexRoles roles{std::vector<char>(n), std::vector<char>(n)};
  for (size_t v = 0; v < n; ++v) {
    // The angle sum of a vertex on a non-manifold edge is not that of one surface: no curvature.
    roles.interior[v] = topo.used[v] && !topo.boundary[v] && !topo.nonmanifold[v];
    roles.constrained[v] = (!problem.constrained.empty() && problem.constrained[v]) ||
                           (params.keep_boundary && topo.boundary[v]) ||
                           (seams == SeamMode::Fixed && topo.seam[v]) || topo.nonmanifold[v] ||
                           topo.in_small_patch[v];
  }
  return roles;
}

double patch_tolerance(const Params& params, int patch_id) {
  const auto it = params.patch_tolerance.find(patch_id);
  return it == params.patch_tolerance.end() ? params.tolerance : it->second;
}

GroupMesh extract_group(const Positions& V, const Triangles& F, const std::vector<int>& faces,
                        const std::vector<int>& face_patch_ids,
                        const std::vector<char>& constrained, const std::vector<char>& interior,
                        const VertexFaces& incident, const Params& params) {
  GroupMesh g;
  std::vector<int> local_vertex(static_cast<size_t>(V.rows()), -1);
  std::vector<char> in_group(static_cast<size_t>(F.rows()), 0);
  for (int f : faces) in_group[static_cast<size_t>(f)] = 1;

  std::vector<char> in_faces(static_cast<size_t>(V.rows()), 0);
  for (int f : faces)
    for (int c = 0; c < 3; ++c) in_faces[static_cast<size_t>(F(f, c))] = 1;
  const auto touches = [&](size_t v) { return in_faces[v] != 0; };
  std::vector<int> ring;
  std::vector<char> in_ring(static_cast<size_t>(F.rows()), 0);
  for (int f : faces)
    for (int c = 0; c < 3; ++c) {
      const auto v = static_cast<size_t>(F(f, c));
      for (int k = incident.start[v]; k < incident.start[v + 1]; ++k) {
        const auto h = static_cast<size_t>(incident.faces[static_cast<size_t>(k)]);
        if (!in_group[h] && !in_ring[h]) {
          in_ring[h] = 1;
          ring.push_back(static_cast<int>(h));
        }
      }
    }

  // A free seam vertex moves the angles of the ring vertices around it: those are measured too
  // (their whole star joins the ring), so the never-worse rule sees both sides of a free seam.
  std::vector<char> measured_ring(static_cast<size_t>(V.rows()), 0);
  for (size_t r = 0, first_layer = ring.size(); r < first_layer; ++r) {
    const int f = ring[r];
    bool moves = false;
    for (int c = 0; c < 3; ++c) {
      const auto v = static_cast<size_t>(F(f, c));
      moves = moves || (!constrained[v] && touches(v));
    }
    for (int c = 0; c < 3 && moves; ++c) {
      const auto u = static_cast<size_t>(F(f, c));
      if (touches(u) || !interior[u] || measured_ring[u]) continue;
      measured_ring[u] = 1;
      for (int k = incident.start[u]; k < incident.start[u + 1]; ++k) {
        const auto h = static_cast<size_t>(incident.faces[static_cast<size_t>(k)]);
        if (!in_group[h] && !in_ring[h]) {
          in_ring[h] = 1;
          ring.push_back(static_cast<int>(h));
        }
      }
    }
  }

  g.solve_faces = static_cast<Eigen::Index>(faces.size());
  g.F.resize(g.solve_faces + static_cast<Eigen::Index>(ring.size()), 3);
  std::vector<char> touched_by_group;
  auto add_face = [&](int f, bool solved) {
    const Eigen::Index row = static_cast<Eigen::Index>(g.global_face.size());
    const int id = face_patch_ids[static_cast<size_t>(f)];
    for (int c = 0; c < 3; ++c) {
      const int v = F(f, c);
      int& l = local_vertex[static_cast<size_t>(v)];
      if (l < 0) {
        l = static_cast<int>(g.global_vertex.size());
        g.global_vertex.push_back(v);
        g.tolerance.push_back(std::numeric_limits<double>::infinity());
        touched_by_group.push_back(0);
      }
      const auto lu = static_cast<size_t>(l);
      if (solved) {
        g.tolerance[lu] = std::min(g.tolerance[lu], patch_tolerance(params, id));
        touched_by_group[lu] = 1;
      }
      g.F(row, c) = l;
    }
    g.global_face.push_back(f);
    g.face_patch.push_back(id);
    g.face_unit.push_back(id);
  };
  for (int f : faces) add_face(f, true);
  g.solve_vertices = static_cast<Eigen::Index>(g.global_vertex.size());
  for (int f : ring) add_face(f, false);

  const size_t n = g.global_vertex.size();
  g.V0.resize(static_cast<Eigen::Index>(n), 3);
  g.fixed.resize(n);
  for (size_t l = 0; l < n; ++l) {
    const auto v = static_cast<size_t>(g.global_vertex[l]);
    g.V0.row(static_cast<Eigen::Index>(l)) = V.row(static_cast<Eigen::Index>(v));
    g.fixed[l] = constrained[v] || !touched_by_group[l];
    if (interior[v] && (touched_by_group[l] || measured_ring[v]))
      g.owned.push_back(static_cast<int>(l));
  }
  // The local and global numberings are inverse maps on the group's vertices.
  assert(std::all_of(g.global_vertex.begin(), g.global_vertex.end(), [&](int v) {
    return g.global_vertex[static_cast<size_t>(local_vertex[static_cast<size_t>(v)])] == v;
  }));
  assert(g.global_face.size() == static_cast<size_t>(g.F.rows()) &&
         g.face_patch.size() == g.global_face.size() && g.tolerance.size() == n);
  g.V_input = g.V0;  // run by itself; the engine gives its own input (quasidev.cpp)
  return g;
}

}  // namespace qd::approximate
