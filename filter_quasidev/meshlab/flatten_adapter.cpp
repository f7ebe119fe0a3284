#include "flatten_adapter.h"

#include <memory>
#include <stdexcept>
#include <utility>

#include "declared_parameters.h"
#include "engine_mesh.h"
#include "flatten/flatten.h"
#include "flatten/stretch_ramp.h"
#include "flatten_figures.h"
#include "flatten_params.h"
#include "io/atomic_file.h"
#include "io/pattern_files.h"
#include "jobs.h"

namespace qdml {

namespace {

// Writes the engine's texture coordinates, stretch and its colour on every live face of m,
// enabling m's per-wedge texture coordinates, face quality and face colour first. Touches
// nothing else.
void write_back(CMeshO& m, const EngineMesh& e, const qd::flatten::FlattenResult& r) {
  using Quality = CMeshO::FaceType::QualityType;
  using TexScalar = CMeshO::FaceType::TexCoordType::ScalarType;
  if (static_cast<std::size_t>(r.uv.rows()) != e.face_slot.size() ||
      r.stretch.size() != e.face_slot.size())
    throw std::logic_error("the flattening returned a result of the wrong size");
  if (!m.face.IsWedgeTexCoordEnabled()) m.face.EnableWedgeTexCoord();
  if (!m.face.IsQualityEnabled()) m.face.EnableQuality();
  if (!m.face.IsColorEnabled()) m.face.EnableColor();
  const qd::common::QualityRange range = qd::flatten::stretch_ramp_range(r.stretch);
  for (std::size_t f = 0; f < e.face_slot.size(); ++f) {
    CMeshO::FaceType& face = m.face[e.face_slot[f]];
    const auto row = static_cast<Eigen::Index>(f);
    for (int k = 0; k < 3; ++k) {
      face.WT(k).U() = static_cast<TexScalar>(r.uv(row, 2 * k));
      face.WT(k).V() = static_cast<TexScalar>(r.uv(row, 2 * k + 1));
      face.WT(k).N() = 0;
    }
    face.Q() = static_cast<Quality>(r.stretch[f]);
    const std::array<unsigned char, 3> c = qd::common::ramp_color(r.stretch[f], range);
    face.C() = vcg::Color4b(c[0], c[1], c[2], 255);
  }
}

// The pattern files asked for, staged (written beside their targets, not yet in place).
std::vector<std::unique_ptr<qd::io::PendingFile>> stage_pattern(
    const qd::flatten::FlattenResult& r, const qd::params::FlattenSettings& s) {
  std::vector<std::unique_ptr<qd::io::PendingFile>> files;
  for (const auto& [path, bytes] : qd::io::pattern_files(s, r.pattern))
    files.push_back(std::make_unique<qd::io::PendingFile>(path, bytes));
  return files;
}

std::string flatten_info() {
  return "Flattens every patch of the mesh into a <b>pattern piece</b> to cut from flat "
         "material: a patch that is not a disk is first cut into one (a tube gets one "
         "shortest cut, said in the log), then flattened as rigidly as possible (ARAP: the "
         "lengths of the flat piece match the mesh's as closely as they can), and the pieces "
         "are laid out side by side at true scale. Run <i>Quasi-Developable Approximation</i> "
         "first to make the patches (nearly) developable: a developable patch flattens "
         "without stretch; one that is not is flattened anyway, with its distortion "
         "reported.<br>"
         "<b>Per-face quality</b> = patch id (rounded to an integer); without it the whole "
         "mesh is one patch. Each edge-connected part of a patch becomes its own piece.<br>"
         "<b>Output</b>: per-wedge texture coordinates in model units (1 unit on the pattern "
         "= 1 unit on the mesh), per-face quality = signed stretch (largest singular value of "
         "the 3D-to-2D map minus 1, negative where compression is larger) replacing the patch "
         "ids, and a face colour ramp on it (green none, blue stretched, red compressed). One "
         "log line per piece: faces, cut, ARAP iterations, largest and mean length distortion, "
         "area and boundary length change, flipped and overlapping faces (a piece with either "
         "is not flattenable without a further cut). The pattern can be written as <b>SVG</b> "
         "(outlines, piece labels, notches where pieces meet, a scale bar) and <b>DXF</b> "
         "(AutoCAD R12 polylines, one layer per patch), each when its file name is given.<br>"
         "Liu L., Zhang L., Xu Y., Gotsman C., Gortler S. J., <i>A local/global approach to "
         "mesh parameterization</i>, Computer Graphics Forum 27(5), SGP 2008.";
}

FilterRun run(CMeshO& m, bool has_face_quality, const ParamValues& values, vcg::CallBackPos* cb) {
  return run_declared(
      qd::params::flatten_params(), values, [&](const qd::params::FlattenSettings& settings) {
        return filter_run(apply_flatten(m, has_face_quality, settings, cb), flatten_figures,
                          {MeshPart::WedgeTexCoord, MeshPart::FaceQuality, MeshPart::FaceColor});
      });
}

}  // namespace

FlattenOutcome apply_flatten(CMeshO& m, bool has_face_quality, const qd::params::FlattenSettings& s,
                             vcg::CallBackPos* cb) {
  return guarded_run<qd::flatten::FlattenResult>([&](FlattenOutcome& out) {
    qd::flatten::FlattenProblem problem;
    const EngineMesh e = read_geometry(m, problem.V, problem.F);
    problem.patch = read_patch_ids(m, e, has_face_quality, true, out.log);
    problem.params = s.engine;
    out.result = qd::flatten::flatten(problem, progress_of(cb));
    const auto files = stage_pattern(out.result, s);
    for (const auto& file : files) file->commit();
    write_back(m, e, out.result);
    out.log.insert(out.log.end(), out.result.log.begin(), out.result.log.end());
    if (!s.svg_file.empty()) out.log.push_back("pattern written as SVG to " + s.svg_file);
    if (!s.dxf_file.empty()) out.log.push_back("pattern written as DXF to " + s.dxf_file);
  });
}

FilterSpec flatten_filter() {
  return {qd::params::kFlattenJob.filter,
          qd::params::kFlattenJob.python,
          flatten_info(),
          {FilterCategory::Texture},
          {MeshPart::WedgeTexCoord, MeshPart::FaceQuality, MeshPart::FaceColor},
          [](const CMeshO&) { return filter_parameters(qd::params::flatten_params()); },
          run};
}

}  // namespace qdml
