// The parameters of the flattening, declared once (see param.h).
#pragma once

#include <vector>

#include "flatten_settings.h"
#include "param.h"

namespace qd::params {

const std::vector<Param<FlattenSettings>>& flatten_params();

}  // namespace qd::params
