// Checks a Problem before any work: throws qd::common::Error with a message that says what was
// wrong and what to do (docs/design.md "Bad input"). Accepts odd but workable input: silently, or
// with a warning where part of the mesh is left as it is. The mesh itself is checked by
// common/validate_mesh.h; this adds the parameters, sizes, patches and free vertices.
#pragma once

#include <string>
#include <vector>

#include "approximate/common_names.h"
#include "approximate/problem.h"
#include "common/topology.h"

namespace qd::approximate {

// Returns the topology it computed, so callers need not compute it again. Fails only when
// nothing can be processed: non-manifold edges and patches too small to fit are kept as they
// are (see warnings()).
Topology validate(const Problem& problem);

// One line per part of the mesh the run keeps as it is (vertices on non-manifold edges,
// patches of fewer than kMinPatchFaces faces), with a count, the first example and what to do.
std::vector<std::string> warnings(const Topology& topology);

}  // namespace qd::approximate
