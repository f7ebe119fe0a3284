// What a user sets for the flattening, in every front end: the engine's parameters and the
// pattern files. flatten_params.cpp declares each field.
#pragma once

#include <string>

#include "choices.h"
#include "flatten/flatten_problem.h"

namespace qd::params {

struct FlattenSettings {
  FlattenParams engine;
  std::string svg_file;  // "" = no SVG pattern
  std::string dxf_file;  // "" = no DXF pattern
  PatternUnit unit = PatternUnit::Model;
};

// The unit the SVG writer states: "" for PatternUnit::Model (no physical unit), else its name.
inline std::string svg_unit(const FlattenSettings& s) {
  return s.unit == PatternUnit::Model ? "" : name_of(kPatternUnits, s.unit);
}

}  // namespace qd::params
