#include "quasidev_adapter.h"

#include <stdexcept>
#include <utility>

#include "engine_mesh.h"  // first: MeshLab's mesh type before the vcg algorithms below

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

#include "approximate/quasidev.h"
#include "approximate/validate.h"
#include "common/mesh.h"
#include "common/quality_range.h"
#include "printf_string.h"
#include "result_figures.h"

namespace qdml {

namespace {

std::size_t count_selected(const std::vector<char>& constrained) {
  std::size_t n = 0;
  for (char c : constrained) n += c ? 1 : 0;
  return n;
}

// Average edge length AE of the live mesh (0 for a mesh without faces).
double average_edge(const qd::Problem& p) {
  return p.F.rows() > 0 ? qd::average_edge_length(p.V, p.F) : 0.0;
}

// Writes the engine's positions, per-vertex quality and (optionally) colours into m, then
// refreshes normals and the bounding box. Touches nothing else.
void write_back(CMeshO& m, const EngineMesh& e, const qd::Result& r, const Settings& s) {
  using Scalar = CMeshO::ScalarType;
  using Quality = CMeshO::VertexType::QualityType;
  const std::vector<double>& quality = s.displacement_quality ? r.displacement : r.k_after;
  if (static_cast<std::size_t>(r.V.rows()) != e.vertex_slot.size() ||
      quality.size() != e.vertex_slot.size())
    throw std::logic_error("the engine returned a result of the wrong size");
  const qd::QualityRange range = qd::robust_quality_range(quality);
  for (std::size_t i = 0; i < e.vertex_slot.size(); ++i) {
    CMeshO::VertexType& v = m.vert[e.vertex_slot[i]];
    const auto row = static_cast<Eigen::Index>(i);
    v.P() = CMeshO::CoordType(static_cast<Scalar>(r.V(row, 0)), static_cast<Scalar>(r.V(row, 1)),
                              static_cast<Scalar>(r.V(row, 2)));
    v.Q() = static_cast<Quality>(quality[i]);
    if (s.colorize) {
      const std::array<unsigned char, 3> c = qd::ramp_color(quality[i], range);
      v.C() = vcg::Color4b(c[0], c[1], c[2], 255);
    }
  }
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
}

// The engine's problem for m: geometry, patch ids (per-face quality when present and wanted),
// constraints (selection) and parameters, with a tolerance of 0 resolved to 1·AE. Says what it
// read in `log`. The mesh is validated before the parameters (with a placeholder tolerance): a
// tolerance derived from a broken mesh (NaN coordinates give a NaN AE, also as the dialog's
// default) would otherwise hide what is really wrong.
qd::Problem make_problem(const CMeshO& m, bool has_face_quality, const Settings& s,
                         std::vector<std::string>& log, EngineMesh& e) {
  qd::Problem problem;
  e = read_geometry(m, problem.V, problem.F);
  problem.patch = read_patch_ids(m, e, has_face_quality, s.use_patches, log);
  problem.constrained = read_selected(m.vert, e.vertex_slot);
  problem.params = s.params;
  problem.params.tolerance = 1;
  qd::validate(problem);
  problem.params.tolerance = s.params.tolerance == 0 ? average_edge(problem) : s.params.tolerance;
  log.push_back(format("%zu selected vertices kept fixed; tolerance %g model units",
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


// The table's run: the values as Settings, apply(), and on success the figures and what was
// written (the colour only when asked for).
FilterRun run(CMeshO& m, bool has_face_quality, const ParamValues& values, vcg::CallBackPos* cb) {
  const Settings settings = settings_from_values(values);
  std::vector<MeshPart> written = {MeshPart::VertexQuality};
  if (settings.colorize) written.push_back(MeshPart::VertexColor);
  return filter_run(apply(m, has_face_quality, settings, cb), result_figures, std::move(written));
}

}  // namespace

std::vector<ParamSpec> parameter_specs(const CMeshO& m) {
  const qd::Params d;
  const Settings ds;
  qd::Problem geometry;
  read_geometry(m, geometry.V, geometry.F);
  const double ae = average_edge(geometry);
  const auto flag = [](bool b) { return b ? 1.0 : 0.0; };
  const auto index = [](auto e) { return static_cast<double>(static_cast<int>(e)); };
  return {
      {"tolerance", "Tolerance (model units)",
       format("delta_err: the most a vertex may move (per iteration or in total, see Tolerance "
              "mode), in model units. The mesh's average edge length AE = %g; 0 means 1 AE. "
              "Smaller keeps the shape closer but leaves more curvature.",
              ae),
       ParamKind::Float, ae, {}, ""},
      {"tolerance_mode", "Tolerance mode",
       "step: the tolerance caps each iteration's move (the paper); total: it caps the whole "
       "move from the original position.",
       ParamKind::Enum, index(d.tolerance_mode), {"step", "total"}, ""},
      {"max_iter", "Max iterations", "Stop after this many iterations per patch.", ParamKind::Int,
       static_cast<double>(d.max_iter), {}, ""},
      {"weight", "Developability weight",
       "w of the paper's Eq. (8): how strongly faces are turned towards their target normals "
       "against keeping their shape. Larger removes more curvature per iteration but moves more.",
       ParamKind::Float, d.weight, {}, ""},
      {"developability", "Developability term",
       "Which rows make each patch developable. curve: the paper's target normals on the curve "
       "fitted to the patch's Gauss image (best for cones, cylinders, lampshades, sleeves); "
       "defect: Gauss-Newton rows that drive every interior angle defect (Gaussian curvature) "
       "to zero (beyond the paper; best for draped, wrinkled panels whose Gauss image is a "
       "blob, not a curve); both; auto: per patch, curve where the curve fits within 5 degrees, "
       "else defect (beyond the paper). The log says which each patch used and why.",
       ParamKind::Enum, index(d.developability), {"curve", "defect", "both", "auto"}, ""},
      {"defect_weight", "Angle-defect weight",
       "w_d of the angle-defect rows against keeping the shape; scale- and density-invariant. "
       "Larger removes more curvature per iteration but moves the surface more.",
       ParamKind::Float, d.defect_weight, {}, ""},
      {"anchor", "Anchor stiffness",
       "alpha of the soft anchors (paper Eq. 15): how strongly vertices near fixed vertices resist "
       "moving; the stiffness fades with the distance (in AE) from fixed vertices.",
       ParamKind::Float, d.anchor, {}, ""},
      {"use_patches", "Patches from face quality",
       "On: faces with the same per-face quality (rounded) form one patch, each made "
       "developable on its own. Off, or without per-face quality: the whole mesh is one patch.",
       ParamKind::Bool, flag(ds.use_patches), {}, ""},
      {"seam_mode", "Seams",
       "fixed: vertices shared by two patches do not move (the paper); free: all patches are "
       "solved together and seam vertices move too, staying shared so no crack opens.",
       ParamKind::Enum, index(d.seams), {"fixed", "free"}, ""},
      {"keep_boundary", "Keep boundary",
       "Keep the vertices of the open mesh boundary fixed.", ParamKind::Bool,
       flag(d.keep_boundary), {}, ""},
      {"target_mode", "Target normals",
       "fixed: fit the Gauss-image curve once (the paper); reproject: project the current normals "
       "onto it every iteration; refit: refit the curve every iteration (slower, strongest).",
       ParamKind::Enum, index(d.targets), {"fixed", "reproject", "refit"}, ""},
      {"stop_abd", "Stop at ratio_ABD (%)",
       "Stop when an iteration lowers the total absolute Gaussian curvature G_ABD by less than "
       "this percentage (paper Eq. 19).",
       ParamKind::Float, d.stop_abd, {}, ""},
      {"stop_obd", "Stop at ratio_OBD (%)",
       "Stop when an iteration lowers the orientation developability D(P) by less than this "
       "percentage (paper Eq. 20).",
       ParamKind::Float, d.stop_obd, {}, ""},
      {"output_quality", "Output quality",
       "What the per-vertex quality holds afterwards: the Gaussian curvature after the filter, "
       "or each vertex's displacement in model units.",
       ParamKind::Enum, flag(ds.displacement_quality), {"curvature", "displacement"}, ""},
      {"colorize", "Colorize", "Colour the vertices by a ramp on the output quality.",
       ParamKind::Bool, flag(ds.colorize), {}, ""},
  };
}

Settings settings_from_values(const ParamValues& values) {
  Settings s;
  qd::Params& p = s.params;
  const auto choice = [&](const char* name, auto fallback) {
    return static_cast<decltype(fallback)>(whole_value(values, name, static_cast<int>(fallback)));
  };
  p.tolerance = number_value(values, "tolerance", p.tolerance);
  p.tolerance_mode = choice("tolerance_mode", p.tolerance_mode);
  p.max_iter = whole_value(values, "max_iter", p.max_iter);
  p.weight = number_value(values, "weight", p.weight);
  p.anchor = number_value(values, "anchor", p.anchor);
  p.developability = choice("developability", p.developability);
  p.defect_weight = number_value(values, "defect_weight", p.defect_weight);
  s.use_patches = flag_value(values, "use_patches", s.use_patches);
  p.seams = choice("seam_mode", p.seams);
  p.keep_boundary = flag_value(values, "keep_boundary", p.keep_boundary);
  p.targets = choice("target_mode", p.targets);
  p.stop_abd = number_value(values, "stop_abd", p.stop_abd);
  p.stop_obd = number_value(values, "stop_obd", p.stop_obd);
  s.displacement_quality = flag_value(values, "output_quality", s.displacement_quality);
  s.colorize = flag_value(values, "colorize", s.colorize);
  return s;
}

Outcome apply(CMeshO& m, bool has_face_quality, const Settings& s, vcg::CallBackPos* cb) {
  return guarded_run<qd::Result>([&](Outcome& out) {
    EngineMesh e;
    const qd::Problem problem = make_problem(m, has_face_quality, s, out.log, e);
    out.result = qd::approximate(problem, progress_of(cb));
    write_back(m, e, out.result, s);
    out.log.insert(out.log.end(), out.result.log.begin(), out.result.log.end());
  });
}

FilterSpec approximate_filter() {
  using C = FilterCategory;
  using P = MeshPart;
  return {"Quasi-Developable Approximation",
          "apply_coord_quasi_developable_approximation",
          filter_info(),
          {C::Smoothing, C::Quality, C::VertexColoring},
          {P::VertexPositions, P::VertexNormals, P::FaceNormals, P::VertexQuality, P::VertexColor},
          parameter_specs,
          run};
}

}  // namespace qdml
