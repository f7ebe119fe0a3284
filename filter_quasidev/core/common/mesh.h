// Triangle mesh and the small helpers every engine step shares.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // Vec3::cross
#include <vector>

namespace qd::common {

using Vec3 = Eigen::Vector3d;
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3>;  // one row per vertex
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3>;     // one row per face, vertex indices

// Unit normal of face f (zero vector for a zero-area face).
Vec3 face_normal(const Positions& V, const Triangles& F, int f);

// Corner 3·f + k of face f at vertex v (its k-th corner), or -1 when f does not use v.
int corner_of(const Triangles& F, int f, int v);

// Area of face f.
double face_area(const Positions& V, const Triangles& F, int f);

// Edge {lo, hi} (lo < hi) of face `face`.
struct FaceEdge {
  int lo, hi, face;
};

// The three edges of every given face (faces empty = all faces), sorted by (lo, hi, face), so
// the faces of one undirected edge are neighbours. Linear time: a counting sort on lo, then
// the few edges of each lo sorted by (hi, face). Vertex indices must lie in [0, vertex_count).
std::vector<FaceEdge> sorted_face_edges(const Triangles& F, Eigen::Index vertex_count,
                                        const std::vector<int>& faces = {});

// Average edge length AE over the given faces (each undirected edge counted once).
// faces empty = all faces.
double average_edge_length(const Positions& V, const Triangles& F,
                           const std::vector<int>& faces = {});

}  // namespace qd::common
