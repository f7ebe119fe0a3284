// OFF reader for the command (OFF, COFF, NOFF, CNOFF, STOFF variants: the first three numbers of a
// vertex line are its position, anything after them is ignored; so are colours after a face's
// indices). Input: the file's bytes. Output: a MeshDocument (polygons fan-triangulated, no patch
// ids). Throws qd::common::Error "OFF line N: ..." on malformed, truncated or out-of-range data.
#pragma once

#include <string_view>

#include "io/mesh_document.h"

namespace qd::io {

MeshDocument parse_off(std::string_view bytes);

}  // namespace qd::io
