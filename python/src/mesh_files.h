// quasidev.read and quasidev.write: mesh files through the command's readers and writer (qd_io).
// read_mesh_file: a PLY, OBJ or OFF file as new arrays (V, F, the patch ids and fixed vertices
// the file holds, or None) with the panel names and the reader's notes. write_mesh_file: V and F
// (already checked by the Python side), the patch ids as face quality, a per-vertex value as
// vertex quality and per-corner texture coordinates as the face texcoord, as binary PLY written
// atomically (the file is replaced only when complete).
// Both release the GIL; qd::common::Error (unreadable file, bad format) becomes ValueError.
#pragma once

#include <nanobind/nanobind.h>

#include <optional>
#include <string>

#include "numpy_arrays.h"

namespace qd::python {

nb::dict read_mesh_file(const std::string& path);

void write_mesh_file(const std::string& path, const VertexArray& V, const FaceArray& F,
                     std::optional<IdArray> patches, std::optional<ValueArray> quality,
                     std::optional<CornerUVArray> uv);

}  // namespace qd::python
