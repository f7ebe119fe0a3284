#include "engine_mesh.h"

#include <cmath>
#include <limits>
#include <set>

#include "common/error.h"
#include "common/format_text.h"

namespace qdml {

EngineMesh read_geometry(const CMeshO& m, qd::common::Positions& V, qd::common::Triangles& F) {
  EngineMesh e;
  std::vector<int> compact(m.vert.size(), -1);
  for (std::size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD()) {
      compact[i] = static_cast<int>(e.vertex_slot.size());
      e.vertex_slot.push_back(i);
    }
  for (std::size_t f = 0; f < m.face.size(); ++f)
    if (!m.face[f].IsD()) e.face_slot.push_back(f);
  V.resize(static_cast<Eigen::Index>(e.vertex_slot.size()), 3);
  for (std::size_t i = 0; i < e.vertex_slot.size(); ++i)
    for (int a = 0; a < 3; ++a)
      V(static_cast<Eigen::Index>(i), a) = static_cast<double>(m.vert[e.vertex_slot[i]].cP()[a]);
  F.resize(static_cast<Eigen::Index>(e.face_slot.size()), 3);
  for (std::size_t f = 0; f < e.face_slot.size(); ++f)
    for (int k = 0; k < 3; ++k)
      F(static_cast<Eigen::Index>(f), k) =
          compact[static_cast<std::size_t>(vcg::tri::Index(m, m.face[e.face_slot[f]].cV(k)))];
  return e;
}

std::vector<int> read_patch_ids(const CMeshO& m, const EngineMesh& e, bool has_face_quality,
                                bool use_patches, std::vector<std::string>& log) {
  if (!has_face_quality || !use_patches) {
    log.push_back(has_face_quality ? "patches from face quality off: the whole mesh is one patch"
                                   : "no per-face quality: the whole mesh is one patch");
    return {};
  }
  std::vector<int> patch(e.face_slot.size());
  for (std::size_t f = 0; f < e.face_slot.size(); ++f) {
    const double q = static_cast<double>(m.face[e.face_slot[f]].cQ());
    if (!std::isfinite(q) || std::fabs(q) > std::numeric_limits<int>::max())
      throw qd::common::Error(qd::common::format_text(
          "face %zu has per-face quality %g, which is not a patch id: set the "
          "per-face quality to an integer patch id per face",
          f, q));
    patch[f] = static_cast<int>(std::lround(q));
  }
  const std::set<int> ids(patch.begin(), patch.end());
  log.push_back(
      qd::common::format_text("patches from per-face quality: %zu patch(es)", ids.size()));
  return patch;
}

qd::common::Progress progress_of(vcg::CallBackPos* cb) {
  return [cb](int percent, const std::string& message) {
    if (cb) cb(percent, message.c_str());
  };
}

}  // namespace qdml
