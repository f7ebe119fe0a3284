// The reference page of one job (docs/reference/<command>.md) as Markdown, made from its
// declared parameters: how each front end runs it, a table of every parameter (name, command
// option and older spellings, type, unit, default, range, MeshLab label), each one's help, and
// what only one front end has and why.
#pragma once

#include <string>
#include <vector>

#include "jobs.h"
#include "param.h"

namespace qd::params {

std::string reference_markdown(const JobNames& job, const std::vector<ParamInfo>& params);

}  // namespace qd::params
