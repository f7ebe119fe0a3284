// D-Charts' Lloyd iteration (Julius, Kraevoy, Sheffer 2005) over the faces to segment. Charts
// are first seeded and grown pass after pass into the faces no chart has yet (chart_growing.h)
// until every face is in one. Each round then refits each chart's cone to its faces
// (cone_fit.h), moves each seed to its chart's most interior face (chart_seeds.h), regrows all
// charts from their seeds, and fills the faces left free the same way. Rounds repeat until no
// chart was added and at most one face in kSettled changed chart, or max_rounds is reached.
//
// Every face of a chart fits the chart's proxy within the limit: faces join only within it, a
// refit never fits the chart's faces worse than the previous axis did, so each chart keeps a
// face within it to be its seed.
#pragma once

#include <vector>

#include "common/progress.h"
#include "segment/chart.h"
#include "segment/chart_growing.h"
#include "segment/common_names.h"
#include "segment/face_geometry.h"
#include "segment/face_graph.h"

namespace qd::segment {

constexpr int kSettled = 100;

struct LloydResult {
  std::vector<int> label;     // per face: chart index, or kOutside where it was kOutside
  std::vector<Chart> charts;  // with the proxy each chart last grew with
  int rounds = 0;             // Lloyd rounds (fill passes not counted)
};

// label: kFree for the faces to segment, kOutside for the others. progress: called once per
// round with a percentage in [percent_from, percent_to].
LloydResult lloyd_charts(const FaceGraph& graph, const FaceGeometry& g, std::vector<int> label,
                         const GrowSettings& settings, int max_rounds, int threads,
                         const Progress& progress, int percent_from, int percent_to);

}  // namespace qd::segment
