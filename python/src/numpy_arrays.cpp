#include "numpy_arrays.h"

#include <limits>
#include <string>

#include "common/error.h"

namespace qd::python {

common::Positions positions_of(const VertexArray& V) {
  const auto n = static_cast<Eigen::Index>(V.shape(0));
  common::Positions out(n, 3);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index k = 0; k < 3; ++k)
      out(i, k) = V(static_cast<size_t>(i), static_cast<size_t>(k));
  return out;
}

common::Triangles triangles_of(const FaceArray& F, std::size_t vertices) {
  const auto m = static_cast<Eigen::Index>(F.shape(0));
  common::Triangles out(m, 3);
  for (Eigen::Index f = 0; f < m; ++f)
    for (Eigen::Index k = 0; k < 3; ++k) {
      const std::int64_t v = F(static_cast<size_t>(f), static_cast<size_t>(k));
      if (v < 0 || static_cast<std::uint64_t>(v) >= vertices)
        throw common::Error("F[" + std::to_string(f) + "] holds vertex " + std::to_string(v) +
                            ", not one of the " + std::to_string(vertices) + " vertices");
      out(f, k) = static_cast<int>(v);
    }
  return out;
}

std::vector<int> ids_of(const IdArray& ids) {
  std::vector<int> out(ids.shape(0));
  for (size_t i = 0; i < out.size(); ++i) {
    const std::int64_t id = ids(i);
    if (id < std::numeric_limits<int>::min() || id > std::numeric_limits<int>::max())
      throw common::Error("patch id " + std::to_string(id) + " does not fit a 32-bit int");
    out[i] = static_cast<int>(id);
  }
  return out;
}

std::vector<char> flags_of(const FlagArray& flags) {
  std::vector<char> out(flags.shape(0));
  for (size_t i = 0; i < out.size(); ++i) out[i] = flags(i) ? 1 : 0;
  return out;
}

nb::ndarray<nb::numpy, double> numpy_positions(const common::Positions& V) {
  std::vector<double> rows(static_cast<size_t>(V.size()));
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    for (Eigen::Index k = 0; k < 3; ++k) rows[static_cast<size_t>(3 * i + k)] = V(i, k);
  return numpy_array(std::move(rows), {static_cast<size_t>(V.rows()), 3});
}

}  // namespace qd::python
