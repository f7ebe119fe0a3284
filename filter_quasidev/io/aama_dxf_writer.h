// The cutting pattern as an AAMA/ASTM DXF file (ASTM D6673, "Standard Practice for Sewn Products
// Pattern Data Interchange—Data Format", after the AAMA DXF of the American Apparel
// Manufacturers Association), in the DXF of AutoCAD Release 12 (AC1009) that AAMA readers take.
// One BLOCK per piece (named PIECE_<label>, '.' as '_'), its points relative to the corner of
// its cut line's box, INSERTed at that corner so the layout is kept. The standard's numbered
// layers (D6673 table of layers; also Lectra/Romans CAD "AAMA layer convention"):
//   1   piece boundary: the outer cut line (closed POLYLINE) and the piece system text
//       "Piece Name: <name, else Piece <label>>" and "Quantity: <n>" (TEXT);
//   4   notches: a LINE per notch, from the cut line through the sew line (slit notch);
//   7   grain line: a LINE through the piece's centroid along the grain;
//   11  internal cut-outs: the cut line of each hole;
//   14  sew lines: every sew line, when the seam allowance is not 0;
//   15  annotation text: the label's lines (piece_marks.h), its size and mirror count among them.
// D6673's "Size:" piece text names the grading size, which a flattened mesh has none of, so the
// piece's measured size is annotation (15) instead. Units: the standard declares them by the
// style system text "Units: METRIC" (millimetres) or "Units: ENGLISH" (inches) on layer 1 outside
// the blocks; R12 has no $INSUNITS, so $MEASUREMENT (1 metric, 0 English) is written as well for
// readers that look there. mm are written as they are, cm as mm (× 10), in as inches.
#pragma once

#include <ostream>
#include <string>

#include "flatten/pattern.h"

namespace qd::io {

// unit: the model's length unit, "mm", "cm" or "in"; anything else throws qd::common::Error
// (an AAMA file must declare its unit and a model unit is none).
void write_aama_dxf(std::ostream& out, const flatten::Pattern& pattern, const std::string& unit);

}  // namespace qd::io
