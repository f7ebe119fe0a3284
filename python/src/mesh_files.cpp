#include "mesh_files.h"

#include <nanobind/stl/map.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <utility>
#include <vector>

#include "common/error.h"
#include "io/atomic_file.h"
#include "io/mesh_reader.h"
#include "io/output_mesh.h"

namespace qd::python {

nb::dict read_mesh_file(const std::string& path) {
  io::MeshDocument mesh;
  {
    nb::gil_scoped_release released;
    mesh = io::read_mesh(path);
  }
  const size_t n = mesh.positions.size(), m = mesh.triangles.size();
  std::vector<double> positions;
  positions.reserve(3 * n);
  for (const auto& p : mesh.positions) positions.insert(positions.end(), p.begin(), p.end());
  std::vector<std::int64_t> triangles;
  triangles.reserve(3 * m);
  for (const auto& t : mesh.triangles) triangles.insert(triangles.end(), t.begin(), t.end());
  nb::dict out;
  out["V"] = numpy_array(std::move(positions), {n, 3});
  out["F"] = numpy_array(std::move(triangles), {m, 3});
  out["patches"] = nb::none();
  if (!mesh.patch.empty())
    out["patches"] =
        numpy_array(std::vector<std::int64_t>(mesh.patch.begin(), mesh.patch.end()), {m});
  out["fixed"] = nb::none();
  if (!mesh.constrained.empty())
    out["fixed"] = numpy_array(
        std::vector<std::uint8_t>(mesh.constrained.begin(), mesh.constrained.end()), {n});
  out["patch_names"] = mesh.patch_names;
  out["notes"] = mesh.notes;
  return out;
}

void write_mesh_file(const std::string& path, const VertexArray& V, const FaceArray& F,
                     std::optional<IdArray> patches, std::optional<ValueArray> quality,
                     std::optional<CornerUVArray> uv) {
  io::MeshDocument doc;
  const size_t n = V.shape(0), m = F.shape(0);
  doc.positions.resize(n);
  for (size_t i = 0; i < n; ++i) doc.positions[i] = {V(i, 0), V(i, 1), V(i, 2)};
  const common::Triangles triangles = triangles_of(F, n);
  doc.triangles.resize(m);
  for (size_t f = 0; f < m; ++f) {
    const auto r = static_cast<Eigen::Index>(f);
    doc.triangles[f] = {triangles(r, 0), triangles(r, 1), triangles(r, 2)};
  }
  if (uv) {
    if (uv->shape(0) != m) throw common::Error("uv must hold one row per face");
    flatten::WedgeUV corners(static_cast<Eigen::Index>(m), 6);
    for (size_t f = 0; f < m; ++f)
      for (size_t k = 0; k < 6; ++k)
        corners(static_cast<Eigen::Index>(f), static_cast<Eigen::Index>(k)) =
            (*uv)(f, k / 2, k % 2);
    io::set_texcoords(doc, corners);
  }
  if (quality)
    io::set_quality(doc, io::Element::Vertex,
                    std::vector<double>(quality->data(), quality->data() + quality->shape(0)));
  if (patches) {
    const std::vector<int> ids = ids_of(*patches);
    io::set_quality(doc, io::Element::Face, std::vector<double>(ids.begin(), ids.end()));
  }
  nb::gil_scoped_release released;
  io::PendingFile file(path, io::serialize_ply(doc, io::PlyFormat::BinaryLittleEndian));
  file.commit();
}

}  // namespace qd::python
