// The JSON documents the command writes (--report) and the Python module returns, as text: keys in
// the order written, NaN and infinities as null, bytes that are not UTF-8 (file names, PLY property
// names in notes) as U+FFFD, so a report is always valid JSON.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace qd::frontend {

using Json = nlohmann::ordered_json;

std::string report_text(const Json& report);

}  // namespace qd::frontend
