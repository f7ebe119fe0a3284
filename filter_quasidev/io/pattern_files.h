// The pattern files a flattening's settings ask for (SVG; DXF plain or AAMA/ASTM D6673), as
// (path, bytes), so every front end writes them the same way. Throws qd::common::Error for
// an AAMA DXF without a physical unit (aama_dxf_writer.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "flatten/pattern.h"
#include "flatten_settings.h"

namespace qd::io {

std::vector<std::pair<std::string, std::string>> pattern_files(
    const params::FlattenSettings& settings, const flatten::Pattern& pattern);

}  // namespace qd::io
