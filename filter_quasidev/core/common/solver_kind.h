// The sparse factorisation back ends a user may choose (paper §5.4), and the size from which
// SolverKind::Auto takes CHOLMOD for a positive-definite matrix (docs/solvers.md).
#pragma once

namespace qd::common {

enum class SolverKind { Auto, Cholmod, EigenLLT, EigenLDLT };

constexpr long kCholmodFromUnknowns = 1500;

}  // namespace qd::common
