#include "quasidev_adapter.h"

// MeshLab's mesh type comes before the vcg algorithms that use it.
// clang-format off
#include "engine_mesh.h"
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
// clang-format on

#include <stdexcept>
#include <utility>

#include "approximate/quasidev.h"
#include "approximate/validate.h"
#include "approximate_params.h"
#include "common/format_text.h"
#include "common/mesh.h"
#include "common/quality_range.h"
#include "declared_parameters.h"
#include "jobs.h"
#include "result_figures.h"

namespace qdml {

namespace {

// A parameter's setting in the engine's log as the filter's dialog shows it: "Label = value".
std::string label_setting(const std::string& name, const std::string& value) {
  for (const qd::params::ParamInfo& p : qd::params::approximate_params())
    if (p.name == name) return p.label + " = " + value;
  return name + " = " + value;
}

using Settings = qd::params::ApproximateSettings;

std::size_t count_selected(const std::vector<char>& constrained) {
  std::size_t n = 0;
  for (char c : constrained) n += c ? 1 : 0;
  return n;
}

// Average edge length AE of the live mesh (0 for a mesh without faces).
double average_edge(const qd::approximate::Problem& p) {
  return p.F.rows() > 0 ? qd::common::average_edge_length(p.V, p.F) : 0.0;
}

// Writes the engine's positions, per-vertex quality and (optionally) colours into m, then
// refreshes normals and the bounding box. Touches nothing else.
void write_back(CMeshO& m, const EngineMesh& e, const qd::approximate::Result& r,
                const Settings& s) {
  using Scalar = CMeshO::ScalarType;
  using Quality = CMeshO::VertexType::QualityType;
  const std::vector<double>& quality =
      s.output_quality == qd::params::QualityKind::Displacement ? r.displacement : r.k_after;
  if (static_cast<std::size_t>(r.V.rows()) != e.vertex_slot.size() ||
      quality.size() != e.vertex_slot.size())
    throw std::logic_error("the engine returned a result of the wrong size");
  const qd::common::QualityRange range = qd::common::robust_quality_range(quality);
  for (std::size_t i = 0; i < e.vertex_slot.size(); ++i) {
    CMeshO::VertexType& v = m.vert[e.vertex_slot[i]];
    const auto row = static_cast<Eigen::Index>(i);
    v.P() = CMeshO::CoordType(static_cast<Scalar>(r.V(row, 0)), static_cast<Scalar>(r.V(row, 1)),
                              static_cast<Scalar>(r.V(row, 2)));
    v.Q() = static_cast<Quality>(quality[i]);
    if (s.colorize) {
      const std::array<unsigned char, 3> c = qd::common::ramp_color(quality[i], range);
      v.C() = vcg::Color4b(c[0], c[1], c[2], 255);
    }
  }
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
}

// The engine's problem for m: geometry, patch ids (per-face quality when present and wanted),
// constraints (selection) and parameters, with the tolerances in model units. Says what it read
// in `log`. The mesh is validated before the parameters (with a placeholder tolerance): a
// tolerance derived from a broken mesh (NaN coordinates give a NaN AE) would otherwise hide
// what is really wrong.
qd::approximate::Problem make_problem(const CMeshO& m, bool has_face_quality, const Settings& s,
                                      std::vector<std::string>& log, EngineMesh& e) {
  qd::approximate::Problem problem;
  e = read_geometry(m, problem.V, problem.F);
  problem.patch = read_patch_ids(m, e, has_face_quality, s.use_patches, log);
  problem.constrained = read_selected(m.vert, e.vertex_slot);
  problem.params = s.engine;
  problem.params.tolerance = 1;
  qd::approximate::validate(problem);
  try {
    problem.params = qd::params::engine_params(s, average_edge(problem), problem.patch);
  } catch (const qd::params::ParamError& error) {
    throw qd::common::Error("Per-patch tolerance (AE) (patch_tolerance_ae) " +
                            std::string(error.what()));
  }
  log.push_back(
      qd::common::format_text("%zu selected vertices kept fixed; tolerance %g model units",
                              count_selected(problem.constrained), problem.params.tolerance));
  return problem;
}

// The filterInfo text: what the filter does, its inputs and outputs, and the paper.
std::string filter_info() {
  return "Makes every patch of the mesh nearly <b>developable</b> (flattenable from sheet material "
         "without stretching) while moving the vertices as little as possible. For each patch the "
         "Gauss image of its face normals is fitted by a curve on the sphere (the normals of a "
         "developable surface lie on one), every face gets the nearest normal on that curve as "
         "its target, and a least-squares solve moves the vertices so each face turns towards "
         "its target while keeping its shape; this repeats until the curvature stops falling. "
         "Draped, wrinkled patches, whose normals do not lie near one curve, instead get rows "
         "that drive their interior angle defects to zero (Gauss-Newton; beyond the paper, "
         "chosen per patch by <i>Developability term</i>). "
         "Connectivity is kept, so texture coordinates and sewing patterns survive; an iteration "
         "that would raise the curvature or flip a face is rejected.<br>"
         "<b>Per-face quality</b> = patch id (rounded to an integer); vertices shared by two "
         "patches are seams. Without per-face quality the whole mesh is one patch.<br>"
         "<b>Selected vertices</b> do not move. The open boundary stays fixed while <i>Keep "
         "boundary</i> is on.<br>"
         "<b>Output</b>: moved vertices, per-vertex quality = Gaussian curvature after the filter "
         "(or the displacement) with a colour ramp (red low, blue high), and one log line per "
         "patch with its figures and the developability term it used.<br>"
         "Zeng L., Liu Y.-J., Chen M., Yuen M.-F., <i>Least squares quasi-developable mesh "
         "approximation</i>, Computer Aided Geometric Design 29(7):565&ndash;578, 2012.";
}

// The table's run: the values as settings, apply(), and on success the figures and what was
// written (the colour only when asked for).
FilterRun run(CMeshO& m, bool has_face_quality, const ParamValues& values, vcg::CallBackPos* cb) {
  return run_declared(qd::params::approximate_params(), values, [&](const Settings& settings) {
    std::vector<MeshPart> written = {MeshPart::VertexQuality};
    if (settings.colorize) written.push_back(MeshPart::VertexColor);
    return filter_run(apply(m, has_face_quality, settings, cb), result_figures, std::move(written));
  });
}

}  // namespace

std::vector<qd::params::ParamInfo> approximate_parameters(const CMeshO& m) {
  qd::approximate::Problem geometry;
  read_geometry(m, geometry.V, geometry.F);
  const std::string ae =
      qd::common::format_text(" This mesh: AE = %g model units.", average_edge(geometry));
  std::vector<qd::params::ParamInfo> parameters =
      filter_parameters(qd::params::approximate_params());
  for (qd::params::ParamInfo& p : parameters)
    if (p.unit == qd::params::Unit::AverageEdge || p.name == "tolerance_model") p.help += ae;
  return parameters;
}

Outcome apply(CMeshO& m, bool has_face_quality, const Settings& s, vcg::CallBackPos* cb) {
  return guarded_run<qd::approximate::Result>([&](Outcome& out) {
    EngineMesh e;
    const qd::approximate::Problem problem = make_problem(m, has_face_quality, s, out.log, e);
    out.result = qd::approximate::approximate(problem, progress_of(cb), label_setting);
    write_back(m, e, out.result, s);
    out.log.insert(out.log.end(), out.result.log.begin(), out.result.log.end());
  });
}

FilterSpec approximate_filter() {
  using C = FilterCategory;
  using P = MeshPart;
  return {qd::params::kApproximateJob.filter,
          qd::params::kApproximateJob.python,
          filter_info(),
          {C::Smoothing, C::Quality, C::VertexColoring},
          {P::VertexPositions, P::VertexNormals, P::FaceNormals, P::VertexQuality, P::VertexColor},
          approximate_parameters,
          run};
}

}  // namespace qdml
