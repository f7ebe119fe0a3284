#include "io/mesh_file.h"

#include <utility>

#include "io/ply_file.h"

namespace qd::meshio {

const char* scalar_type_name(ScalarType type) {
  switch (type) {
    case ScalarType::Int8:
      return "char";
    case ScalarType::UInt8:
      return "uchar";
    case ScalarType::Int16:
      return "short";
    case ScalarType::UInt16:
      return "ushort";
    case ScalarType::Int32:
      return "int";
    case ScalarType::UInt32:
      return "uint";
    case ScalarType::Float32:
      return "float";
    case ScalarType::Float64:
      return "double";
  }
  return "?";
}

std::size_t scalar_type_size(ScalarType type) {
  switch (type) {
    case ScalarType::Int8:
    case ScalarType::UInt8:
      return 1;
    case ScalarType::Int16:
    case ScalarType::UInt16:
      return 2;
    case ScalarType::Int32:
    case ScalarType::UInt32:
    case ScalarType::Float32:
      return 4;
    case ScalarType::Float64:
      return 8;
  }
  return 0;
}

PlyProperty scalar_property(const std::string& name, ScalarType type, std::vector<double> values) {
  PlyProperty p;
  p.name = name;
  p.type = type;
  p.values = std::move(values);
  return p;
}

int PlyElement::find(const std::string& property_name) const {
  for (std::size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == property_name) return static_cast<int>(i);
  return -1;
}

const PlyElement* PlyFile::find(const std::string& element_name) const {
  for (const PlyElement& e : elements)
    if (e.name == element_name) return &e;
  return nullptr;
}

}  // namespace qd::meshio
