// A mesh made of k known developable pieces is split into exactly those pieces, each with the
// right proxy and topology.
#include <gtest/gtest.h>

#include "segment/segment.h"
#include "segment/segment_log.h"
#include "segment_checks.h"
#include "segment_meshes.h"

namespace qd::test {
namespace {

using namespace qd::common;
using namespace qd::segment;

TEST(SegmentPieces, CappedCylinderIsACylinderAndTwoDiscs) {
  const MeshBuilder b = capped_cylinder();
  const SegmentResult r = segment_into_pieces(b.pieces(), b.problem());
  for (const SegmentPatch& s : r.patches) {
    EXPECT_LT(s.max_error_deg, 1e-3);
    EXPECT_NEAR(std::abs(s.proxy.axis.z()), 1.0, 1e-6);
    if (s.proxy.angle > 1.0) {  // the side
      EXPECT_STREQ(proxy_kind(s.proxy), "cylinder");
      EXPECT_EQ(s.boundary_loops, 2);
      EXPECT_EQ(s.euler, 0);
      EXPECT_FALSE(s.disk);
    } else {
      EXPECT_STREQ(proxy_kind(s.proxy), "plane");
      EXPECT_EQ(s.boundary_loops, 1);
      EXPECT_TRUE(s.disk);
    }
  }
}

// Without creases the fit alone must find the pieces.
TEST(SegmentPieces, CappedCylinderWithoutCreases) {
  const MeshBuilder b = capped_cylinder();
  SegmentProblem p = b.problem();
  p.params.crease_deg = 180;
  segment_into_pieces(b.pieces(), p);
}

TEST(SegmentPieces, ConeOnCylinderIsTwoPieces) {
  const MeshBuilder b = cone_on_cylinder();
  const SegmentResult r = segment_into_pieces(b.pieces(), b.problem());
  bool cone = false;
  for (const SegmentPatch& s : r.patches)
    if (std::string(proxy_kind(s.proxy)) == "cone") {
      cone = true;
      // The facets' plane is at the apothem r·cos(π/48) of each ring.
      EXPECT_NEAR(s.proxy.angle, std::atan2(1.0, std::cos(M_PI / 48)), 1e-9);
    }
  EXPECT_TRUE(cone);
}

TEST(SegmentPieces, CubeIsSixPlanes) {
  const MeshBuilder b = cube();
  const SegmentResult r = segment_into_pieces(b.pieces(), b.problem());
  for (const SegmentPatch& s : r.patches) {
    EXPECT_STREQ(proxy_kind(s.proxy), "plane");
    EXPECT_TRUE(s.disk);
  }
}

}  // namespace
}  // namespace qd::test
