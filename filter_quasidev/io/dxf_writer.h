// The cutting pattern as a plain DXF file of AutoCAD Release 12 (AC1009), the version cutting
// tables, plotters and CAD programs all read (Autodesk, "AutoCAD Release 12 DXF Reference"). Per
// piece, on layers named after its patch <id>:
//   PATCH_<id>          the cut line(s) as closed POLYLINEs and the label as TEXT lines (name,
//                       piece, quantity, size; piece_marks.h) at its centroid;
//   PATCH_<id>_SEW      the sew line(s), dashed, when the seam allowance is not 0;
//   PATCH_<id>_NOTCHES  the notches as LINEs cut through the allowance;
//   PATCH_<id>_GRAIN    the grainline as a LINE;
// so a cutter can switch each off. Coordinates in model units, z = 0. For the AAMA/ASTM D6673
// layout see aama_dxf_writer.h.
#pragma once

#include <ostream>
#include <string>

#include "flatten/pattern.h"

namespace qd::io {

// unit: the model's length unit written in the labels' size ("" = model units).
void write_dxf(std::ostream& out, const flatten::Pattern& pattern, const std::string& unit = "");

}  // namespace qd::io
