#include "mesh_geometry.h"

#include <array>
#include <tuple>

namespace qd::cli {

namespace {

// rows (one std::array per row) as an Eigen matrix with as many columns.
template <typename Matrix, typename Row>
Matrix matrix_of(const std::vector<Row>& rows) {
  Matrix m(static_cast<Eigen::Index>(rows.size()),
           static_cast<Eigen::Index>(std::tuple_size<Row>::value));
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t k = 0; k < rows[i].size(); ++k)
      m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = rows[i][k];
  return m;
}

}  // namespace

common::Positions positions_of(const io::MeshDocument& mesh) {
  return matrix_of<common::Positions>(mesh.positions);
}

common::Triangles triangles_of(const io::MeshDocument& mesh) {
  return matrix_of<common::Triangles>(mesh.triangles);
}

}  // namespace qd::cli
