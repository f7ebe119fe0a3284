// The segmentation's parameters, in the MeshLab dialog's order. Defaults:
// qd::segment::SegmentParams and SegmentSettings.
#include "segment_params.h"

#include "declare.h"

namespace qd::params {

namespace {

using S = SegmentSettings;

std::vector<Param<S>> declare() {
  using P = SegmentParams;
  return {
      real("max_error_deg", field(&S::engine, &P::max_error_deg), Unit::Degrees, above_to(0, 90),
           "Largest fit error (deg)",
           "The largest angle between a face normal and its patch's fitted cone, cylinder or "
           "plane: patches are split until every face is within it. Smaller gives more, flatter "
           "patches (at 20, pieces meeting at 40 degrees or more are told apart).")
          .alias("--max-error"),
      integer("min_faces", field(&S::engine, &P::min_faces), Unit::Faces, closed(1, 1000000000),
              "Smallest patch (faces)",
              "No patch has fewer faces (unless the part between kept borders is smaller). A part "
              "too curved to fit at this size becomes one patch over the limit, and the log says "
              "so."),
      real("min_area", field(&S::engine, &P::min_area), Unit::Fraction, below(0, 1),
           "Smallest patch (area fraction)",
           "When above 0, no patch has less than this fraction of the mesh area."),
      integer("target_patches", field(&S::engine, &P::target_patches), Unit::Patches,
              closed(0, 1000000000), "Target patch count",
              "The number of patches wanted; 0 = as many as the fit needs. More are merged (best "
              "fitting first, even over the limit), fewer are split.")
          .alias("--target"),
      boolean("keep_patches", field(&S::keep_patches), "Keep existing patches",
              "The input's patch ids (MeshLab: per-face quality; the command: PLY face quality or "
              "patch, OBJ groups) are existing patches: each whose faces fit within the largest "
              "fit error is kept whole, only the others are split."),
      boolean("selection_border", field(&S::selection_border), "Keep selection border",
              "No patch crosses the border between selected and unselected faces (the command: "
              "PLY face flags with the selection bit 0x20)."),
      real("crease_deg", field(&S::engine, &P::crease_deg), Unit::Degrees, above_to(0, 180),
           "Crease angle (deg)",
           "Where the mesh is split, edges whose two faces' normals differ by more than this stay "
           "patch borders, so no patch folds over a sharp edge; 180 = none. (A part that fits one "
           "cone as a whole, such as two planes meeting at a fold, is kept whole.)")
          .alias("--crease"),
      integer("max_rounds", field(&S::engine, &P::max_rounds), Unit::Iterations, closed(1, 1000),
              "Max Lloyd rounds",
              "Lloyd rounds (re-fit every patch, re-grow them all) after the first growth, at "
              "most; they stop earlier once the patches settle."),
      threads(field(&S::engine, &P::threads),
              "Threads; 0 = all cores. The result does not depend on it."),
  };
}

}  // namespace

const std::vector<Param<SegmentSettings>>& segment_params() {
  static const std::vector<Param<SegmentSettings>> params = declare();
  return params;
}

}  // namespace qd::params
