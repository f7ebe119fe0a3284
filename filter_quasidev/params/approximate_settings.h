// What a user sets for the approximation, in every front end (the command, the MeshLab
// filters): the engine's parameters, the tolerance in AE or model units, and what the output's
// vertex quality and colour hold. approximate_params.cpp declares each field as a parameter.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "approximate/params.h"
#include "choices.h"
#include "param.h"

namespace qd::params {

using approximate::Params;

struct ApproximateSettings {
  Params engine;                             // tolerance and patch_tolerance: see engine_params()
  double tolerance_ae = 1.0;                 // δ_err in units of AE
  double tolerance_model = 0.0;              // δ_err in model units; 0 = tolerance_ae
  std::map<int, double> patch_tolerance_ae;  // δ_err per patch id, in AE
  bool use_patches = true;                   // patch ids from the input (else one patch)
  QualityKind output_quality = QualityKind::Curvature;
  bool colorize = true;          // a colour ramp on the output quality
  std::string constraints_file;  // the command's list of fixed vertices ("" = none)
};

// The engine's parameters for a mesh of average edge length `average_edge` whose faces have
// the patch ids `patch` (empty = one patch 0): δ_err in model units, per patch too. Throws
// ParamError when patch_tolerance_ae names a patch the mesh does not have.
Params engine_params(const ApproximateSettings& s, double average_edge,
                     const std::vector<int>& patch);

// patch_tolerance_ae as text, "ID=X,ID=X" ("" for none), and back: adds the entries of a text
// of ID=X items (separated by commas or spaces) to `into`; throws ParamError on bad syntax or a
// value that is not above 0.
std::string patch_tolerance_text(const std::map<int, double>& tolerances);
void parse_patch_tolerance(const std::string& text, std::map<int, double>& into);

}  // namespace qd::params
