// Panel names: OBJ groups' names and PLY "comment patch <id> <name…>" lines name the patches.
#include <gtest/gtest.h>

#include "io/obj_reader.h"
#include "io/ply_mesh.h"

using namespace qd::io;

namespace {

TEST(PanelNames, ObjGroupsNameTheirPatches) {
  const MeshDocument m = parse_obj(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "f 1 2 3\n"                    // before any group: the unnamed patch 0
      "g  back   panel \nf 1 3 4\n"  // patch 1, its words joined by one space
      "o front\nf 1 2 4\n"
      "g back panel\nf 2 3 4\n"
      "g unused\n");
  EXPECT_EQ(m.patch, (std::vector<int>{0, 1, 2, 1}));
  EXPECT_EQ(m.patch_names, (std::map<int, std::string>{{1, "back panel"}, {2, "front"}}));
  // The names become the PLY comments the output carries, which name the patches when read back.
  EXPECT_EQ(m.comments, (std::vector<std::string>{"patch 1 back panel", "patch 2 front"}));
}

TEST(PanelNames, PlyCommentsNameTheirPatchesAndAreKept) {
  const MeshDocument m = parse_ply(
      "ply\nformat ascii 1.0\n"
      "comment patch 3 left  sleeve\n"
      "comment patch x not an id\n"
      "comment patch 4\n"  // no name
      "comment made by hand\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nproperty int patch\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 3\n");
  EXPECT_EQ(m.patch, (std::vector<int>{3}));
  EXPECT_EQ(m.patch_names, (std::map<int, std::string>{{3, "left  sleeve"}}));
  EXPECT_EQ(m.comments.size(), 4u);
}

}  // namespace
