// The engine's entry point: Algorithm 1 of the paper over every patch of a mesh.
#pragma once

#include "approximate/common_names.h"
#include "approximate/problem.h"
#include "approximate/result.h"
#include "approximate/setting_text.h"
#include "common/progress.h"

namespace qd::approximate {

// Validates the problem, runs Step 1 (target normals) and Step 2 (deformation) on every patch
// (or on all patches jointly with free seams), and returns the new positions and reports.
// setting: how the front end names a parameter's setting in the log. Throws qd::common::Error on
// bad input; the input is never modified.
Result approximate(const Problem& problem, const Progress& progress = {},
                   const SettingText& setting = {});

}  // namespace qd::approximate
