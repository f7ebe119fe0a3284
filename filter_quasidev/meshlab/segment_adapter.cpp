#include "segment_adapter.h"

#include <algorithm>
#include <stdexcept>

#include "common/format_text.h"
#include "declared_parameters.h"
#include "engine_mesh.h"
#include "jobs.h"
#include "segment/patch_color.h"
#include "segment/segment.h"
#include "segment_figures.h"
#include "segment_params.h"

namespace qdml {

namespace {

// Enables per-face quality and colour if needed, then writes the patch id and its colour.
void write_back(CMeshO& m, const EngineMesh& e, const qd::segment::SegmentResult& r) {
  if (r.patch.size() != e.face_slot.size())
    throw std::logic_error("the segmentation returned a result of the wrong size");
  if (!m.face.IsQualityEnabled()) m.face.EnableQuality();
  if (!m.face.IsColorEnabled()) m.face.EnableColor();
  for (std::size_t f = 0; f < e.face_slot.size(); ++f) {
    CMeshO::FaceType& face = m.face[e.face_slot[f]];
    face.Q() = static_cast<CMeshO::FaceType::QualityType>(r.patch[f]);
    const std::array<unsigned char, 3> c = qd::segment::patch_color(r.patch[f]);
    face.C() = vcg::Color4b(c[0], c[1], c[2], 255);
  }
}

// The filterInfo text: what the filter does, its inputs and outputs, and the paper.
std::string filter_info() {
  return "Splits the mesh into nearly <b>developable</b> patches (each can be cut from flat "
         "sheet material with little stretching), the step before <i>Quasi-Developable "
         "Approximation</i>. Every patch is grown around a fitted cone, cylinder or plane "
         "(D-Charts: Lloyd iterations on a cost of fit, compactness and boundary straightness, "
         "then merging of neighbouring patches whose union still fits) until every face normal "
         "is within <i>Largest fit error</i> of its patch's cone. The border of the face "
         "selection always stays a patch border; where the mesh is split, so do sharp edges "
         "(above <i>Crease angle</i>).<br>"
         "<b>Per-face quality</b> on input: with <i>Keep existing patches</i>, the patch id "
         "(rounded); each existing patch that fits is kept whole, the others are split.<br>"
         "<b>Output</b>: per-face quality = patch id 0..k-1 (what the approximation reads) and a "
         "face colour per patch; one log line per patch (faces, area, fitted proxy, fit error, "
         "boundary loops, whether it is a disk) and a total. Vertices do not move.<br>"
         "Julius D., Kraevoy V., Sheffer A., <i>D-Charts: Quasi-Developable Mesh "
         "Segmentation</i>, Computer Graphics Forum 24(3), Eurographics 2005.";
}

// The table's run: the values as settings, apply_segment(), and on success the figures.
FilterRun run(CMeshO& m, bool has_face_quality, const ParamValues& values, vcg::CallBackPos* cb) {
  return run_declared(
      qd::params::segment_params(), values, [&](const qd::params::SegmentSettings& settings) {
        return filter_run(apply_segment(m, has_face_quality, settings, cb), segment_figures,
                          {MeshPart::FaceQuality, MeshPart::FaceColor});
      });
}

}  // namespace

SegmentOutcome apply_segment(CMeshO& m, bool has_face_quality, const qd::params::SegmentSettings& s,
                             vcg::CallBackPos* cb) {
  return guarded_run<qd::segment::SegmentResult>([&](SegmentOutcome& out) {
    qd::segment::SegmentProblem problem;
    const EngineMesh e = read_geometry(m, problem.V, problem.F);
    if (s.keep_patches) problem.patch = read_patch_ids(m, e, has_face_quality, true, out.log);
    if (s.selection_border) problem.selected = read_selected(m.face, e.face_slot);
    if (!problem.selected.empty())
      out.log.push_back(
          qd::common::format_text("the border of %zu selected faces kept",
                                  static_cast<std::size_t>(std::count(problem.selected.begin(),
                                                                      problem.selected.end(), 1))));
    problem.params = s.engine;
    out.result = qd::segment::segment(problem, progress_of(cb));
    write_back(m, e, out.result);
    out.log.insert(out.log.end(), out.result.log.begin(), out.result.log.end());
  });
}

FilterSpec segment_filter() {
  using C = FilterCategory;
  using P = MeshPart;
  return {qd::params::kSegmentJob.filter,
          qd::params::kSegmentJob.python,
          filter_info(),
          {C::Quality, C::FaceColoring},
          {P::FaceQuality, P::FaceColor},
          [](const CMeshO&) { return filter_parameters(qd::params::segment_params()); },
          run};
}

}  // namespace qdml
