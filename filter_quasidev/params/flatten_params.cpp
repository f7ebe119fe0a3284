// The flattening's parameters, in the MeshLab dialog's order. Defaults: qd::FlattenParams and
// FlattenSettings.
#include "flatten_params.h"

#include "declare.h"

namespace qd::params {

namespace {

using S = FlattenSettings;

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
      save_file("svg_file", field(&S::svg_file), ".svg", "SVG pattern file",
                "Write the cutting pattern as SVG to this file: outlines, piece labels, notches, a "
                "scale bar; empty = no SVG. In MeshLab a relative path is relative to its working "
                "folder.")
          .alias("--svg"),
      save_file("dxf_file", field(&S::dxf_file), ".dxf", "DXF pattern file",
                "Write the cutting pattern as DXF to this file: AutoCAD R12 polylines, one layer "
                "per patch, notches on layers of their own; empty = no DXF.")
          .alias("--dxf"),
      choice("unit", field(&S::unit), kPatternUnits, "Model unit",
             "The model's length unit, written on the SVG's scale bar; mm, cm or in also give the "
             "SVG that physical size, so it prints at 1:1."),
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
