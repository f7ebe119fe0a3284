// The words of a Result's enums and figures, for the edges that show them: the engine's log
// (approximate_log.h), the command's JSON report and the MeshLab figures.
#pragma once

#include <string>
#include <vector>

#include "approximate/result.h"

namespace qd::approximate {

// "none", "curve", "defect", "both".
const char* term_name(Term t);

// "curve", "closed curve", "plane", "unchanged".
const char* target_kind_name(TargetKind k);

// "all patches at once", "seams held", "seams free"; "" for the only pass.
const char* pass_name(SolvePass pass);

// "mostly seams", "curvature on seams".
const char* join_reason_name(JoinReason r);

// Why a patch takes its term; the race's figures when it was measured.
std::string term_choice_text(const PatchReport& p);

// Why one pass of a patch stopped, with the figure that decided.
std::string pass_stop_text(const PassStop& s);

// The stops of every pass: "seams held: ...; then seams free: ...".
std::string stop_reason_text(const std::vector<PassStop>& stops);

}  // namespace qd::approximate
