// PLY reader: ascii, binary_little_endian and binary_big_endian; every scalar type; list
// properties; comment / obj_info lines; elements of any name (kept as tables).
// Input: the file's bytes. Output: a PlyTables. Throws qd::common::Error with a one-line message
// naming the place (header line, data line or byte offset) on any malformed, truncated or absurd
// input. Never reads past the buffer and never allocates more than the file's size can justify.
#pragma once

#include <string_view>

#include "io/ply_tables.h"

namespace qd::io {

PlyTables parse_ply_tables(std::string_view bytes);

}  // namespace qd::io
