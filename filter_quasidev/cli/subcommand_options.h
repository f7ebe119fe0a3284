// The options of each subcommand, registered on its CLI11 App (options.cpp makes the Apps).
#pragma once

#include "options.h"

namespace CLI {
class App;
}

namespace qd::cli {

void add_approximate_options(CLI::App& job, ApproximateOptions& o);
void add_segment_options(CLI::App& job, SegmentOptions& o);
void add_flatten_options(CLI::App& job, FlattenOptions& o);

}  // namespace qd::cli
