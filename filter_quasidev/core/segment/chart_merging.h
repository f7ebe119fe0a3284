// Merging adjacent charts, best-fitting pair first: the union of two charts is fitted with a
// cone (cone_fit.h) and pairs are merged in the order better_fit() gives their unions' cones,
// re-fitting the pairs of a merged chart as they change. Three rules share this loop:
//   WithinLimit  D-Charts' chart merging (Julius, Kraevoy, Sheffer 2005): adjacent charts whose
//                union still fits within the limit;
//   SmallCharts  a chart below the smallest size goes into the neighbour it fits best, even over
//                the limit: the merged chart is then marked OverLimit::SmallestSize if both were
//                below the smallest size, else OverLimit::SmallPart;
//   TargetCount  any adjacent pair, even over the limit (OverLimit::TargetCount), until only the
//                wanted number of charts is left.
// TargetCount, which the user asked for, also merges across creases.
// Ties go to the lower chart indices; the merged chart keeps the lower index. Deterministic for
// any number of threads.
#pragma once

#include "segment/face_geometry.h"
#include "segment/face_graph.h"
#include "segment/partition.h"

namespace qd::segment {

enum class MergeRule { WithinLimit, SmallCharts, TargetCount };

struct MergeSettings {
  double limit = 0.0;  // radians
  int min_faces = 1;   // smallest chart
  double min_area = 0.0;
  int target = 0;  // TargetCount: charts wanted
  int threads = 1;
};

// Returns the number of merges done.
int merge_charts(Partition& p, const FaceGraph& graph, const FaceGeometry& g, MergeRule rule,
                 const MergeSettings& s);

}  // namespace qd::segment
