// A colour per patch id, shared by the command and the filters, so one patch looks the same in
// both: hues a golden angle apart (neighbouring ids far apart on the colour wheel), bright and
// moderately saturated so the shading still reads.
#pragma once

#include <array>

namespace qd::segment {

// Red, green, blue of patch `id` (>= 0).
std::array<unsigned char, 3> patch_color(int id);

}  // namespace qd::segment
