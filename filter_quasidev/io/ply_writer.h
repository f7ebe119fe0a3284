// PLY writer. serialize_ply_tables turns tables into the bytes of a PLY file in any of the three
// formats (the command writes binary little-endian; the others serve round-trip tests).
// Throws qd::common::Error if a value does not fit its declared type (e.g. a list longer than its
// count type allows).
#pragma once

#include <string>

#include "io/ply_tables.h"

namespace qd::io {

std::string serialize_ply_tables(const PlyTables& ply, PlyFormat format);

}  // namespace qd::io
