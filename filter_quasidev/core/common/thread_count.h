// How many threads a job uses: the `threads` parameter, or every core when it is 0.
#pragma once

#include <cstddef>

namespace qd::common {

size_t thread_count(int requested);

}  // namespace qd::common
