// A mesh splits into pieces: one per patch and edge-connected component, bow-ties separated.
#include <gtest/gtest.h>

#include "flatten/piece.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

TEST(Pieces, PatchesAndComponentsBecomePieces) {
  // Four triangles in a row: 0–1 share an edge, 2–3 share an edge, 1–2 share only vertex 3.
  qd::common::Positions V(8, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0, 2, 2, 0, 1, 2, 0, 3, 2, 0;
  qd::common::Triangles F(4, 3);
  F << 0, 1, 2, 1, 3, 2, 3, 4, 5, 3, 5, 6;
  const std::vector<qd::flatten::Piece> one_patch = qd::flatten::extract_pieces(V, F, {});
  ASSERT_EQ(one_patch.size(), 2u);  // the bow-tie at vertex 3 separates them
  EXPECT_EQ(one_patch[0].face, (std::vector<int>{0, 1}));
  EXPECT_EQ(one_patch[1].face, (std::vector<int>{2, 3}));
  EXPECT_EQ(one_patch[1].component, 1);
  EXPECT_EQ(one_patch[1].components, 2);
  for (const qd::flatten::Piece& p : one_patch) {
    EXPECT_EQ(p.V.rows(), 4);
    for (int v = 0; v < p.V.rows(); ++v) EXPECT_EQ(p.V.row(v), V.row(p.vertex[v]));
    for (int f = 0; f < p.F.rows(); ++f)
      for (int k = 0; k < 3; ++k) EXPECT_EQ(p.vertex[p.F(f, k)], F(p.face[f], k));
  }
  // Patch 7 is face 0 and faces 2–3, which share no vertex: two components of one patch.
  const std::vector<qd::flatten::Piece> by_patch = qd::flatten::extract_pieces(V, F, {7, 5, 7, 7});
  ASSERT_EQ(by_patch.size(), 3u);
  EXPECT_EQ(by_patch[0].patch, 5);
  EXPECT_EQ(by_patch[1].patch, 7);
  EXPECT_EQ(by_patch[1].face, (std::vector<int>{0}));
  EXPECT_EQ(by_patch[2].face, (std::vector<int>{2, 3}));
  EXPECT_EQ(by_patch[2].components, 2);
}

}  // namespace
