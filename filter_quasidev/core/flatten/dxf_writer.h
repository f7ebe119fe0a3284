// The cutting pattern as a DXF file of AutoCAD Release 12 (AC1009), the version cutting tables,
// plotters and CAD programs all read (Autodesk, "AutoCAD Release 12 DXF Reference"): per boundary
// loop one closed POLYLINE (VERTEX … SEQEND) on the layer PATCH_<id> of its patch, the piece's
// label as a TEXT at its centroid on the same layer, and its notches as LINEs on the layer
// PATCH_<id>_NOTCHES, so a cutter can switch them off. Coordinates in model units, z = 0.
#pragma once

#include <ostream>

#include "flatten/pattern.h"

namespace qd {

void write_dxf(std::ostream& out, const Pattern& pattern);

}  // namespace qd
