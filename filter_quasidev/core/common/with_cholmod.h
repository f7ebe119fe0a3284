// Whether this build of the engine has CHOLMOD: qd_core has, qd_core_eigen (the plugins whose
// host ships no SuiteSparse) has not. Only the solver sources compiled once per build
// (QD_SOLVER_SOURCES in core/CMakeLists.txt) may read it.
#pragma once

namespace qd::common {

#ifdef QD_WITH_CHOLMOD
constexpr bool kHaveCholmod = true;
#else
constexpr bool kHaveCholmod = false;
#endif

}  // namespace qd::common
