#include "approximate/patch_fit.h"

#include <map>
#include <memory>

#include "approximate/common_names.h"
#include "approximate/validate.h"
#include "common/error.h"
#include "common/metrics.h"

namespace qd::approximate {
namespace {

// The model of a patch Step 1 could not fit (e.g. its normals fill the sphere): every face
// keeps its own normal as target, so the patch keeps its shape.
class KeepNormals : public GaussModel {
 public:
  Vec3 project(const Vec3& n, int&) const override { return n; }
  TargetKind kind() const override { return TargetKind::Unchanged; }
};

void normals_and_areas(const Positions& X, const Triangles& F, const std::vector<int>& faces,
                       std::vector<Vec3>& normals, std::vector<double>& areas) {
  normals.clear();
  areas.clear();
  for (int f : faces) {
    normals.push_back(face_normal(X, F, f));
    areas.push_back(face_area(X, F, f));
  }
}

PatchFit fit_patch(int id, const std::vector<int>& faces, const std::vector<Vec3>& normals,
                   const std::vector<double>& areas, size_t threads) {
  PatchFit p;
  p.id = id;
  p.faces = faces;
  if (faces.size() < static_cast<size_t>(kMinPatchFaces)) {
    p.skipped = "fewer than " + std::to_string(kMinPatchFaces) + " faces, too few to fit";
  } else {
    try {
      p.fit = fit_targets(normals, areas, threads);
      return p;
    } catch (const Error& e) {
      p.skipped = e.what();
    }
  }
  p.fit.model = std::make_shared<KeepNormals>();
  p.fit.targets = normals;
  return p;
}

bool has_defects(Term t) { return t == Term::Defect || t == Term::Both; }

}  // namespace

bool PatchFit::planar() const {
  return fit.model->kind() == TargetKind::Plane && fit.residual_deg < kPlanarResidualDeg;
}

std::vector<PatchFit> fit_patches(const GroupMesh& g, const Positions& X, size_t threads) {
  std::map<int, std::vector<int>> faces_of;
  for (Eigen::Index f = 0; f < g.solve_faces; ++f)
    faces_of[g.face_patch[static_cast<size_t>(f)]].push_back(static_cast<int>(f));
  std::vector<PatchFit> fits;
  std::vector<Vec3> normals;
  std::vector<double> areas;
  for (auto& [id, faces] : faces_of) {
    normals_and_areas(X, g.F, faces, normals, areas);
    fits.push_back(fit_patch(id, faces, normals, areas, threads));
  }
  return fits;
}

void choose_term(PatchFit& p, Developability mode) {
  p.term = Term::None;
  if (p.planar() || p.faces.size() < static_cast<size_t>(kMinPatchFaces)) {
    p.reason = p.planar() ? TermReason::Planar : TermReason::TooSmall;
    return;
  }
  p.reason = TermReason::AsAsked;
  switch (mode) {
    case Developability::Curve:
      p.term = p.fitted() ? Term::Curve : Term::None;
      return;
    case Developability::Defect:
      p.term = Term::Defect;
      return;
    case Developability::Both:
      p.term = p.fitted() ? Term::Both : Term::Defect;
      if (!p.fitted()) p.reason = TermReason::NoCurveFits;
      return;
    case Developability::Auto:
      p.reason = TermReason::Measured;  // the race sets the term
      return;
  }
}

std::vector<Term> candidate_terms(const PatchFit& p, Eigen::Index vertices) {
  if (!p.fitted()) return {Term::Defect};
  if (vertices > kMaxDefectRaceVertices) return {Term::Curve};
  return {Term::Curve, Term::Defect, Term::Both};
}

std::vector<Vec3> group_targets(const GroupMesh& g, const std::vector<PatchFit>& fits) {
  std::vector<Vec3> t(static_cast<size_t>(g.solve_faces), Vec3::Zero());
  for (const PatchFit& p : fits)
    if (p.term != Term::Defect)
      for (size_t k = 0; k < p.faces.size(); ++k)
        t[static_cast<size_t>(p.faces[k])] = p.fit.targets[k];
  return t;
}

Retarget make_retarget(const GroupMesh& g, const std::vector<PatchFit>& fits, size_t threads) {
  return [&g, &fits, threads](const Positions& X, TargetMode mode) {
    if (mode == TargetMode::Refit) {
      std::vector<PatchFit> refits = fit_patches(g, X, threads);
      for (size_t k = 0; k < refits.size(); ++k) refits[k].term = fits[k].term;
      return group_targets(g, refits);
    }
    std::vector<Vec3> t(static_cast<size_t>(g.solve_faces), Vec3::Zero());
    std::vector<Vec3> normals;
    for (const PatchFit& p : fits) {
      if (p.term == Term::Defect) continue;
      normals.clear();
      for (int f : p.faces) normals.push_back(face_normal(X, g.F, f));
      const std::vector<Vec3> targets = project_normals(*p.fit.model, normals, threads);
      for (size_t k = 0; k < p.faces.size(); ++k) t[static_cast<size_t>(p.faces[k])] = targets[k];
    }
    return t;
  };
}

bool refits_when_stalled(const std::vector<PatchFit>& fits, const Params& params) {
  if (params.targets != TargetMode::ReprojectThenRefit || params.stop_rule != StopRule::Plateau)
    return false;
  return std::any_of(fits.begin(), fits.end(), [](const PatchFit& p) {
    return (p.term == Term::Curve || p.term == Term::Both) && p.fitted() && !p.planar();
  });
}

std::vector<char> group_defect_rows(const GroupMesh& g, const std::vector<PatchFit>& fits) {
  std::vector<char> has_row(g.fixed.size(), 0);
  for (const PatchFit& p : fits)
    if (has_defects(p.term))
      for (int f : p.faces)
        for (int c = 0; c < 3; ++c) has_row[static_cast<size_t>(g.F(f, c))] = 1;
  std::vector<char> interior(g.fixed.size(), 0);
  for (int v : g.owned) interior[static_cast<size_t>(v)] = 1;
  bool any = false;
  for (size_t v = 0; v < has_row.size(); ++v) {
    has_row[v] = has_row[v] && interior[v] && !g.fixed[v];
    any = any || has_row[v];
  }
  if (!any) return {};
  return has_row;
}

}  // namespace qd::approximate
