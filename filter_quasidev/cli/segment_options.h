// The options of `quasidev segment`, registered on its CLI11 App (options.cpp makes the App),
// with their defaults from qd::SegmentParams.
#pragma once

#include "options.h"

namespace CLI {
class App;
}

namespace qd::cli {

void add_segment_options(CLI::App& job, SegmentOptions& o);

}  // namespace qd::cli
