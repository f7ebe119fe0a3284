// The flattening's parameters, in the MeshLab dialog's order. Defaults: qd::flatten::FlattenParams
// and FlattenSettings.
#include "flatten_params.h"

#include "declare.h"

namespace qd::params {

namespace {

using S = FlattenSettings;

const char* const kCommandLibraries =
    "The marker (libnest2d with NLopt) and the PDF (cairo) need libraries that the pymeshlab wheel "
    "does not ship, which a plugin must not need: save the filter's output mesh and run quasidev "
    "flatten on it.";

std::vector<Param<S>> declare() {
  using P = FlattenParams;
  return {
      integer("arap_max_iter", field(&S::engine, &P::max_iterations), Unit::Iterations,
              closed(0, 100000), "Max ARAP iterations",
              "Stop flattening a piece after this many ARAP iterations (each one rotation fit per "
              "face and one linear solve); 0 = the initial flattening only.")
          .alias("--max-iter"),
      real("arap_tolerance", field(&S::engine, &P::tolerance), Unit::Fraction, below(0, 1),
           "ARAP tolerance",
           "Stop a piece's ARAP iterations when its energy changes by less than this fraction "
           "from one iteration to the next. Smaller is more exact and slower.")
          .alias("--tolerance"),
      real("gap", field(&S::engine, &P::gap), Unit::ModelUnits, at_least(0), "Gap between pieces",
           "Space between pieces on the sheet; 0 = 5 % of the largest piece's longer side."),
      real("notch_spacing", field(&S::engine, &P::notch_spacing), Unit::ModelUnits, at_least(0),
           "Notch spacing",
           "Notches mark where pieces meet along a seam, at its ends and this far apart along it, "
           "so they can be matched when sewn; 0 = an eighth of the largest piece's longer side."),
      real("seam_allowance", field(&S::engine, &P::seam_allowance), Unit::ModelUnits, at_least(0),
           "Seam allowance",
           "Width of the seam allowance: the cut line runs this far outside the sew line, with "
           "mitred corners cut off where they would stick out; 0 = cut on the sew line."),
      text<S>(
          "grain_direction", "X,Y,Z|longest", Unit::None,
          [](const S& s) { return direction_text(s.engine.grain_up); },
          [](S& s, const std::string& t) { s.engine.grain_up = parse_direction(t); },
          "Grain direction (3D)",
          "The 3D direction the grainlines follow, e.g. the mesh's up axis 0,1,0: each piece's "
          "grainline is this direction as its flattening maps it; a piece it crosses at nearly a "
          "right angle takes its longest axis instead. longest: every piece's longest axis, "
          "pointing the way y leans on it (for sleeves held out sideways). The pieces are turned "
          "so their grainlines are parallel."),
      real("symmetry_tolerance", field(&S::engine, &P::symmetry_tolerance), Unit::Percent,
           closed(0, 100), "Symmetry tolerance",
           "Pieces that are congruent or mirror images (left and right sleeves) within this share "
           "of their size are one pattern piece to cut several times, turned over where needed; "
           "0 = every piece on its own."),
      save_file("svg_file", field(&S::svg_file), ".svg", "SVG pattern file",
                "Write the cutting pattern as SVG to this file: outlines, piece labels, notches, a "
                "scale bar; empty = no SVG. In MeshLab a relative path is relative to its working "
                "folder.")
          .alias("--svg"),
      save_file("dxf_file", field(&S::dxf_file), ".dxf", "DXF pattern file",
                "Write the cutting pattern as DXF to this file: AutoCAD R12 polylines, one layer "
                "per patch, notches on layers of their own; empty = no DXF.")
          .alias("--dxf"),
      choice("dxf_style", field(&S::dxf_style), kDxfStyles, "DXF style",
             "plain: one layer per patch (any CAD program); aama: the AAMA/ASTM D6673 layout that "
             "garment CAD and cutting tables import (a block per piece, its standard layers, "
             "units declared)."),
      choice("unit", field(&S::unit), kPatternUnits, "Model unit",
             "The model's length unit, written on the SVG's scale bar; mm, cm or in also give the "
             "SVG that physical size, so it prints at 1:1."),
      real("marker_width", field(&S::marker_width), Unit::ModelUnits, at_least(0), "Marker width",
           "Nest every piece to cut (with its quantity and seam allowance) on a fabric this wide, "
           "grainlines along its length, and report the marker's length and efficiency; 0 = no "
           "marker.")
          .alias("--marker")
          .only(kCommand, kCommandLibraries),
      save_file("marker_svg_file", field(&S::marker_svg_file), ".svg", "Marker SVG file",
                "Write the nested marker as SVG to this file; empty = none.")
          .alias("--marker-svg")
          .only(kCommand, kCommandLibraries),
      save_file("marker_dxf_file", field(&S::marker_dxf_file), ".dxf", "Marker DXF file",
                "Write the nested marker as DXF to this file; empty = none.")
          .alias("--marker-dxf")
          .only(kCommand, kCommandLibraries),
      save_file(
          "pdf_file", field(&S::pdf_file), ".pdf", "Printable PDF file",
          "Write the pattern at true scale as a PDF tiled onto pages, with overlap marks, page "
          "numbers, an assembly map and a 5 cm test square; needs a unit other than model.")
          .alias("--pdf")
          .only(kCommand, kCommandLibraries),
      choice("paper", field(&S::paper), kPapers, "Paper", "The printable PDF's page size.")
          .only(kCommand, kCommandLibraries),
      choice(
          "solver", field(&S::engine, &P::solver), kSolverKinds, "Sparse solver",
          "The sparse Cholesky back end of each piece's ARAP system: auto, cholmod, eigen-llt or "
          "eigen-ldlt; the result is the same.")
          .only(kCommand, kSpeedOnly),
      threads(field(&S::engine, &P::threads),
              "Pieces flattened at once; 0 = all cores. The result does not depend on it."),
  };
}

}  // namespace

const std::vector<Param<FlattenSettings>>& flatten_params() {
  static const std::vector<Param<FlattenSettings>> params = declare();
  return params;
}

}  // namespace qd::params
