// What a user sets for the flattening, in every front end: the engine's parameters and the
// pattern files. flatten_params.cpp declares each field.
#pragma once

#include <string>

#include "choices.h"
#include "flatten/flatten_problem.h"

namespace qd::params {

using flatten::FlattenParams;

struct FlattenSettings {
  FlattenParams engine;
  std::string svg_file;  // "" = no SVG pattern
  std::string dxf_file;  // "" = no DXF pattern
  DxfStyle dxf_style = DxfStyle::Plain;
  PatternUnit unit = PatternUnit::Model;
  double marker_width = 0;      // fabric width of the nested marker, model units; 0 = no marker
  std::string marker_svg_file;  // "" = no marker SVG
  std::string marker_dxf_file;  // "" = no marker DXF
  std::string pdf_file;         // "" = no printable PDF
  Paper paper = Paper::A4;
};

// The grain direction's value for "each piece's longest axis" (a zero direction).
inline const char* const kLongestAxis = "longest";

// "X,Y,Z" of a direction ("longest" for 0,0,0), and back; parse_direction throws ParamError
// unless the text is "longest" or three finite numbers, not all 0.
std::string direction_text(const Eigen::Vector3d& d);
Eigen::Vector3d parse_direction(const std::string& text);

// The unit the SVG writer states: "" for PatternUnit::Model (no physical unit), else its name.
inline std::string svg_unit(const FlattenSettings& s) {
  return s.unit == PatternUnit::Model ? "" : name_of(kPatternUnits, s.unit);
}

}  // namespace qd::params
