#include "mesh_geometry.h"

namespace qd::cli {

Positions positions_of(const meshio::MeshFile& mesh) {
  Positions V(static_cast<Eigen::Index>(mesh.positions.size()), 3);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    for (int k = 0; k < 3; ++k)
      V(static_cast<Eigen::Index>(i), k) = mesh.positions[i][static_cast<std::size_t>(k)];
  return V;
}

Triangles triangles_of(const meshio::MeshFile& mesh) {
  Triangles F(static_cast<Eigen::Index>(mesh.triangles.size()), 3);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k)
      F(static_cast<Eigen::Index>(f), k) = mesh.triangles[f][static_cast<std::size_t>(k)];
  return F;
}

}  // namespace qd::cli
