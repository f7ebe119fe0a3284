// The figures of a qd::approximate::Result as the filter returns them (see result_figures.h).
#include "result_figures.h"

#include <algorithm>

namespace qdml {

namespace {

// The developability term a patch used, as the index of that value of the parameter
// "developability" (curve 0, defect 1, both 2); -1 when the patch was left unchanged.
int developability_code(const qd::approximate::PatchReport& p) {
  switch (p.developability) {
    case qd::approximate::Term::Curve:
      return 0;
    case qd::approximate::Term::Defect:
      return 1;
    case qd::approximate::Term::Both:
      return 2;
    case qd::approximate::Term::None:
      break;
  }
  return -1;
}

}  // namespace

std::map<std::string, Figure> result_figures(const qd::approximate::Result& r) {
  const qd::common::Figures& before = r.total_before;
  const qd::common::Figures& after = r.total_after;
  int iterations = 0;
  for (const qd::approximate::PatchReport& p : r.patches)
    iterations = std::max(iterations, p.iterations);
  // Eq. (20) over the whole run; both OBDs are measured against the initial targets.
  const double obd_reduction = before.obd > 0 ? 100.0 * (before.obd - after.obd) / before.obd : 0.0;
  const double ae = r.average_edge;
  using P = qd::approximate::PatchReport;
  return {
      {"abd_reduction", r.abd_reduction},
      {"obd_reduction", obd_reduction},
      {"max_abs_k_before", before.max_abs_k},
      {"max_abs_k_after", after.max_abs_k},
      {"angle_defect_before", before.angle_defect},
      {"angle_defect_after", after.angle_defect},
      {"max_displacement", after.max_disp},
      {"max_displacement_ae", after.max_disp / ae},
      {"mean_displacement", after.mean_disp},
      {"mean_displacement_ae", after.mean_disp / ae},
      {"average_edge", ae},
      {"iterations", iterations},
      {"factorizations", r.factorizations},
      {"patches", static_cast<int>(r.patches.size())},
      {"warnings", static_cast<int>(r.warnings.size())},
      {"time_ms", r.time_ms},
      {"patch_id", figure_list(r.patches, [](const P& p) { return p.id; })},
      {"patch_faces", figure_list(r.patches, [](const P& p) { return p.faces; })},
      {"patch_iterations", figure_list(r.patches, [](const P& p) { return p.iterations; })},
      {"patch_abd_reduction", figure_list(r.patches, [](const P& p) { return p.abd_reduction; })},
      {"patch_obd_reduction", figure_list(r.patches, [](const P& p) { return p.obd_reduction; })},
      {"patch_fit_residual_deg",
       figure_list(r.patches, [](const P& p) { return p.fit_residual_deg; })},
      {"patch_developability", figure_list(r.patches, developability_code)},
      {"patch_max_displacement",
       figure_list(r.patches, [](const P& p) { return p.after.max_disp; })},
      {"patch_max_abs_k_after",
       figure_list(r.patches, [](const P& p) { return p.after.max_abs_k; })},
  };
}

}  // namespace qdml
