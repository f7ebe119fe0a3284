#include "ply_test_util.h"

#include "ply_mesh.h"
#include "ply_reader.h"

namespace qd::meshio::test {

PlyProperty scalar(const std::string& name, ScalarType type, std::vector<double> values) {
  PlyProperty p;
  p.name = name;
  p.type = type;
  p.values = std::move(values);
  return p;
}

PlyProperty list(const std::string& name, ScalarType count_type, ScalarType type,
                 const std::vector<std::vector<double>>& lists) {
  PlyProperty p;
  p.name = name;
  p.is_list = true;
  p.count_type = count_type;
  p.type = type;
  p.offsets.push_back(0);
  for (const auto& l : lists) {
    p.values.insert(p.values.end(), l.begin(), l.end());
    p.offsets.push_back(p.values.size());
  }
  return p;
}

PlyFile sample_ply() {
  PlyFile ply;
  ply.comments = {"made by the test", "second comment"};
  ply.obj_info = {"some info"};
  PlyElement v;
  v.name = "vertex";
  v.count = 5;
  v.properties = {scalar("x", ScalarType::Float32, {0, 1, 1, 0, 2}),
                  scalar("y", ScalarType::Float32, {0, 0, 1, 1, 0.5}),
                  scalar("z", ScalarType::Float32, {0, 0, 0, 0, 0.25}),
                  scalar("flags", ScalarType::Int32, {0, 0, 0, 0, 0x20}),
                  scalar("temperature", ScalarType::Int16, {-7, 3, 100, -32768, 32767})};
  PlyElement f;
  f.name = "face";
  f.count = 3;
  f.properties = {
      list("vertex_indices", ScalarType::UInt8, ScalarType::Int32, {{0, 1, 2}, {0, 2, 3}, {1, 4, 2, 0}}),
      list("texcoord", ScalarType::UInt8, ScalarType::Float32,
           {{0, 0, 1, 0, 1, 1}, {0, 0, 1, 1, 0, 1}, {0.5f, 0.25f, 0.75f, 0.125f, 1, 0.5f, 0, 0}}),
      scalar("quality", ScalarType::Float32, {1, 1, 2.2f})};
  PlyElement e;
  e.name = "edge";
  e.count = 2;
  e.properties = {scalar("vertex1", ScalarType::UInt32, {0, 4000000000.0}),
                  scalar("weight", ScalarType::Float64, {0.1, 1e-300})};
  ply.elements = {v, f, e};
  return ply;
}

MeshFile mesh_of(const std::string& bytes) { return mesh_from_ply(parse_ply(bytes)); }

}  // namespace qd::meshio::test
