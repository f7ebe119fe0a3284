// The layouts of a group's deformation systems: each is computed once and handed to every
// system that asks for the same defect rows, M's is shared by all, and a system on a shared
// layout solves as one that computed its own.
#include <gtest/gtest.h>

#include "approximate/deformation_system.h"
#include "approximate/group_mesh.h"
#include "approximate/system_layout.h"
#include "common/metrics.h"
#include "test_meshes.h"

namespace qd {
namespace {

using namespace qd::approximate;
using namespace qd::common;

struct Group {
  Problem p = test::bumpy_cylinder(8, 4, 0.2);
  GroupMesh g;
  std::vector<char> every_free;  // a defect row on every free vertex
  Group() {
    const size_t nv = static_cast<size_t>(p.V.rows()), nf = static_cast<size_t>(p.F.rows());
    std::vector<int> faces(nf);
    for (size_t f = 0; f < nf; ++f) faces[f] = static_cast<int>(f);
    std::vector<char> constrained(nv, 0), interior(nv, 1);
    constrained[0] = constrained[9] = 1;
    g = extract_group(p.V, p.F, faces, std::vector<int>(nf, 0), constrained, interior,
                      VertexFaces(p.F, p.V.rows()), p.params);
    for (size_t v = 0; v < g.fixed.size(); ++v) every_free.push_back(!g.fixed[v]);
  }
};

TEST(SystemLayouts, EachLayoutIsComputedOnce) {
  const Group s;
  SystemLayouts layouts(s.g, s.p.params, 0.4);
  const SystemLayout none = layouts.get({}), rows = layouts.get(s.every_free),
                     again = layouts.get(s.every_free);
  EXPECT_EQ(none.augmented, nullptr);
  ASSERT_NE(rows.augmented, nullptr);
  EXPECT_EQ(none.matrix, rows.matrix) << "M's order and pattern do not depend on the rows";
  EXPECT_EQ(rows.augmented, again.augmented);
  const std::vector<char> no_rows(s.g.fixed.size(), 0);
  EXPECT_EQ(layouts.get(no_rows).augmented, nullptr);
}

TEST(SystemLayouts, ASystemOnASharedLayoutSolvesAsItsOwn) {
  const Group s;
  Params params = s.p.params;
  params.method = SolveMethod::Direct;
  SystemLayouts layouts(s.g, params, 0.4);
  Positions ref = s.g.V0;
  const Eigen::Index nf = s.g.F.rows();
  std::vector<Vec3> zero(static_cast<size_t>(nf), Vec3::Zero()), normals;
  for (Eigen::Index f = 0; f < nf; ++f)
    normals.push_back(face_normal(s.g.V0, s.g.F, static_cast<int>(f)));
  // Two systems on one layout, set apart by their targets, then one on its own layout.
  DeformationSystem first(s.g, params, layouts.get(s.every_free)),
      second(s.g, params, layouts.get(s.every_free)), own(s.g, params, 0.4, s.every_free);
  const VertexAngles angles = vertex_angles(ref, s.g.F);
  first.set_rows(zero, first.linearise_defects_at(ref, angles));
  second.set_rows(normals, second.linearise_defects_at(ref, angles));
  own.set_rows(normals, own.linearise_defects_at(ref, angles));
  const Positions a = first.solve(ref), b = second.solve(ref), c = own.solve(ref);
  EXPECT_GT((a - b).norm(), 1e-6) << "the targets differ, so must the solutions";
  EXPECT_LT((b - c).norm(), 1e-12 * c.norm());
}

}  // namespace
}  // namespace qd
