// The parameters of the approximation, declared once (see param.h).
#pragma once

#include <vector>

#include "approximate_settings.h"
#include "param.h"

namespace qd::params {

const std::vector<Param<ApproximateSettings>>& approximate_params();

}  // namespace qd::params
