#include "io/result_document.h"

#include <string>

#include "common/error.h"
#include "common/quality_range.h"
#include "flatten/stretch_ramp.h"
#include "io/output_mesh.h"
#include "segment/patch_color.h"

namespace qd::io {

namespace {

std::vector<std::array<unsigned char, 3>> ramp_colors(const std::vector<double>& values,
                                                      const common::QualityRange& range) {
  std::vector<std::array<unsigned char, 3>> colors;
  colors.reserve(values.size());
  for (double value : values) colors.push_back(common::ramp_color(value, range));
  return colors;
}

}  // namespace

MeshDocument approximated_document(const MeshDocument& mesh, const approximate::Result& result,
                                   const params::ApproximateSettings& settings) {
  const std::vector<double>& q = settings.output_quality == params::QualityKind::Curvature
                                     ? result.k_after
                                     : result.displacement;
  const std::size_t vertex_count = mesh.positions.size();
  if (static_cast<std::size_t>(result.V.rows()) != vertex_count || q.size() != vertex_count)
    throw common::Error("internal error: the engine returned " + std::to_string(result.V.rows()) +
                        " positions and " + std::to_string(q.size()) + " quality values for " +
                        std::to_string(vertex_count) + " vertices");
  MeshDocument doc = mesh;
  set_positions(doc, result.V);
  set_quality(doc, Element::Vertex, q);
  if (settings.colorize)
    set_colors(doc, Element::Vertex, ramp_colors(q, common::robust_quality_range(q)));
  return doc;
}

MeshDocument segmented_document(const MeshDocument& mesh, const segment::SegmentResult& result) {
  if (result.patch.size() != mesh.triangles.size())
    throw common::Error("internal error: the segmentation returned " +
                        std::to_string(result.patch.size()) + " patch ids for " +
                        std::to_string(mesh.triangles.size()) + " faces");
  MeshDocument doc = mesh;
  set_quality(doc, Element::Face, std::vector<double>(result.patch.begin(), result.patch.end()));
  std::vector<std::array<unsigned char, 3>> colors;
  colors.reserve(result.patch.size());
  for (int id : result.patch) colors.push_back(segment::patch_color(id));
  set_colors(doc, Element::Face, colors);
  return doc;
}

MeshDocument flattened_document(const MeshDocument& mesh, const flatten::FlattenResult& result) {
  const std::size_t face_count = mesh.triangles.size();
  if (static_cast<std::size_t>(result.uv.rows()) != face_count ||
      result.stretch.size() != face_count)
    throw common::Error("internal error: the flattening returned " +
                        std::to_string(result.uv.rows()) + " texture coordinate rows and " +
                        std::to_string(result.stretch.size()) + " stretch values for " +
                        std::to_string(face_count) + " faces");
  MeshDocument doc = mesh;
  set_texcoords(doc, result.uv);
  set_quality(doc, Element::Face, result.stretch);
  set_colors(doc, Element::Face,
             ramp_colors(result.stretch, flatten::stretch_ramp_range(result.stretch)));
  return doc;
}

}  // namespace qd::io
