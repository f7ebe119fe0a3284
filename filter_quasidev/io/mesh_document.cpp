#include "io/mesh_document.h"

#include "io/ply_tables.h"

namespace qd::io {

PlyProperty scalar_property(const std::string& name, ScalarType type,
                            const std::vector<double>& values) {
  PlyProperty p;
  p.name = name;
  p.values = ScalarColumn(type, values);
  return p;
}

int PlyElement::find(const std::string& property_name) const {
  for (std::size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == property_name) return static_cast<int>(i);
  return -1;
}

const PlyElement* PlyTables::find(const std::string& element_name) const {
  for (const PlyElement& e : elements)
    if (e.name == element_name) return &e;
  return nullptr;
}

}  // namespace qd::io
