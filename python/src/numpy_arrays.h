// Arrays between numpy and the engine: the engine's mesh from C-contiguous numpy arrays (checked:
// indices within the vertices), and new numpy arrays that own their data (Python frees them).
#pragma once

#include <nanobind/ndarray.h>

#include <cstdint>
#include <initializer_list>
#include <utility>
#include <vector>

#include "common/mesh.h"

namespace qd::python {

namespace nb = nanobind;

using VertexArray = nb::ndarray<const double, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu>;
using FaceArray = nb::ndarray<const std::int64_t, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu>;
using IdArray = nb::ndarray<const std::int64_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using FlagArray = nb::ndarray<const bool, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using ValueArray = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using CornerUVArray = nb::ndarray<const double, nb::shape<-1, 3, 2>, nb::c_contig, nb::device::cpu>;

common::Positions positions_of(const VertexArray& V);
// F's rows; qd::common::Error when an index is not a vertex of V.
common::Triangles triangles_of(const FaceArray& F, std::size_t vertices);
// One int per entry; qd::common::Error when one does not fit an int.
std::vector<int> ids_of(const IdArray& ids);
std::vector<char> flags_of(const FlagArray& flags);

// A new numpy array of the given shape holding `data` (row-major), owned by Python.
template <typename T>
nb::ndarray<nb::numpy, T> numpy_array(std::vector<T> data, std::initializer_list<size_t> shape) {
  auto* held = new std::vector<T>(std::move(data));
  nb::capsule owner(held, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
  return nb::ndarray<nb::numpy, T>(held->data(), shape.size(), shape.begin(), owner);
}

// V's rows as a new (n, 3) numpy array.
nb::ndarray<nb::numpy, double> numpy_positions(const common::Positions& V);

}  // namespace qd::python
