#include "ply_test_util.h"

#include "io/ply_mesh.h"
#include "io/ply_reader.h"

namespace qd::io::test {

PlyProperty list(const std::string& name, ScalarType count_type, ScalarType type,
                 const std::vector<std::vector<double>>& lists) {
  PlyProperty p;
  p.name = name;
  p.is_list = true;
  p.count_type = count_type;
  p.values = ScalarColumn(type);
  p.offsets.push_back(0);
  for (const auto& l : lists) {
    for (double v : l) p.values.push_back(v);
    p.offsets.push_back(p.values.size());
  }
  return p;
}

PlyTables sample_ply() {
  PlyTables ply;
  ply.comments = {"made by the test", "second comment"};
  ply.obj_info = {"some info"};
  PlyElement v;
  v.name = "vertex";
  v.count = 5;
  v.properties = {scalar_property("x", ScalarType::Float32, {0, 1, 1, 0, 2}),
                  scalar_property("y", ScalarType::Float32, {0, 0, 1, 1, 0.5}),
                  scalar_property("z", ScalarType::Float32, {0, 0, 0, 0, 0.25}),
                  scalar_property("flags", ScalarType::Int32, {0, 0, 0, 0, 0x20}),
                  scalar_property("temperature", ScalarType::Int16, {-7, 3, 100, -32768, 32767})};
  PlyElement f;
  f.name = "face";
  f.count = 3;
  f.properties = {
      list("vertex_indices", ScalarType::UInt8, ScalarType::Int32,
           {{0, 1, 2}, {0, 2, 3}, {1, 4, 2, 0}}),
      list("texcoord", ScalarType::UInt8, ScalarType::Float32,
           {{0, 0, 1, 0, 1, 1}, {0, 0, 1, 1, 0, 1}, {0.5f, 0.25f, 0.75f, 0.125f, 1, 0.5f, 0, 0}}),
      scalar_property("quality", ScalarType::Float32, {1, 1, 2.2f})};
  PlyElement e;
  e.name = "edge";
  e.count = 2;
  e.properties = {scalar_property("vertex1", ScalarType::UInt32, {0, 4000000000.0}),
                  scalar_property("weight", ScalarType::Float64, {0.1, 1e-300})};
  ply.elements = {v, f, e};
  return ply;
}

MeshDocument mesh_of(const std::string& bytes) { return parse_ply(bytes); }

}  // namespace qd::io::test
