// Seed faces: a chart's new seed after its proxy is refitted (D-Charts' seed update of the
// Lloyd iteration), and the seed of a new chart in a part no chart could take (D-Charts'
// re-seeding where the fit error is exceeded). Both take the part's most interior face: the
// most hops from its border, so the chart can grow the same way in every direction.
#pragma once

#include <vector>

#include "segment/face_graph.h"

namespace qd::segment {

constexpr int kNoBorder = 1 << 30;  // hops of a face in a part with no border (a closed part)

// For each of `faces`, the fewest hops over the face graph to a face of its label whose side has
// no neighbour or a neighbour of another label (0 for those faces); kNoBorder for other faces.
// `faces` must hold every face with the same label next to one of them.
std::vector<int> hops_to_border(const FaceGraph& graph, const std::vector<int>& label,
                                const std::vector<int>& faces);

// For each label 0 … count−1, the face with the most hops among its faces with deviation at
// most `limit` (deviation empty: all 0); ties go to the smaller deviation, then the lower index.
// −1 where no face is eligible. Faces with a negative label are skipped.
std::vector<int> interior_faces(const std::vector<int>& hops, const std::vector<int>& label,
                                int count, const std::vector<double>& deviation, double limit);

}  // namespace qd::segment
