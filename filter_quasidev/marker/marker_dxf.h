// A marker as a DXF file of AutoCAD Release 12 (AC1009; Autodesk, "AutoCAD Release 12 DXF
// Reference"): the fabric's rectangle as a closed POLYLINE on the layer FABRIC, each placed cut
// line as a closed POLYLINE on the layer PIECE_<label> of its piece. Model units, z = 0.
#pragma once

#include <ostream>

#include "marker.h"

namespace qd::marker {

void write_marker_dxf(std::ostream& out, const Marker& marker, const flatten::Pattern& pattern);

}  // namespace qd::marker
