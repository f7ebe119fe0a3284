// User parameters of the segmentation into nearly developable patches (D-Charts: Julius,
// Kraevoy, Sheffer, "D-Charts: Quasi-Developable Mesh Segmentation", Eurographics 2005).
// Angles are in degrees, sizes in faces or as a fraction of the mesh area.
#pragma once

namespace qd::segment {

// Exponents α, β, γ of the fitting, compactness and boundary terms of D-Charts' growing cost
// (growing_cost.h); only their ratios matter. Chosen by measurement (qd_segment_bench, 20°
// limit, on the shared bowl, wingnut, low-resolution spot and shirt and a 100k-face torus):
// with α = 1, β ∈ {0, ¼, ½, 1} × γ ∈ {0, ½, 1, 2, 3, 4}, β = ½, γ = 2 gave among the shortest
// seams (total seam length / √area) without more patches over the limit.
struct CostWeights {
  double fit = 1.0, compactness = 0.5, boundary = 2.0;
};

struct SegmentParams {
  // Largest angle between a face normal and its patch's cone (the fit error the report gives):
  // patches are split until every face is within it (D-Charts' largest fitting error). 20° by
  // measurement (qd_segment_bench --approximate -- --seams free, on the shared low-resolution
  // spot, wingnut, bowl and shirt): at 10° they give 57, 25, 29, 152 patches, 38 and 28 of
  // spot's and the shirt's over the limit at the smallest size; at 20° 43, 9, 11, 42 patches,
  // 7 and 1 over, and the approximation after it removes more G_ABD on bowl and shirt (14.3
  // and 30.1 % against 5.7 and 9.7 %), about as much on spot (4.5 against 4.8 %) and less on
  // wingnut (0.4 against 1.3 %). Larger limits give fewer patches still, but
  // two developable pieces whose normals meet at an angle δ below the crease angle fit one cone
  // once the limit reaches δ/2: at 20° pieces meeting at 40–60° (a cone on a cylinder) are
  // still told apart, at 30° none are.
  double max_error_deg = 20.0;
  // Smallest patch: at least this many faces and, when min_area > 0, this fraction of the mesh
  // area. A part too curved to fit at this size becomes a patch of this size over the limit,
  // and the report says so.
  int min_faces = 20;
  double min_area = 0.0;
  // Number of patches wanted; 0 = as many as the fit needs. More patches than this are merged
  // (best fitting pairs first, even over the limit: the report says so); fewer are split.
  int target_patches = 0;
  // Edges whose faces' normals differ by more than this are kept as borders, so no patch folds
  // over a sharp edge (beyond D-Charts; 180 = none). 60°: the shared wingnut's sharp seam
  // curves (256 edges) and spot's ears and horns (55) are above it, the bowl has no edge above
  // 9°, and a coarse cylinder of eight facets (45° apart) stays whole.
  double crease_deg = 60.0;
  CostWeights weights;
  // Lloyd rounds after the first growth, at most (they stop earlier once settled, lloyd.h); ten
  // fit better than one and thirty no better than ten (docs/measurements-behind-the-code.md).
  int max_rounds = 10;
  int threads = 0;  // 0 = all cores
};

}  // namespace qd::segment
