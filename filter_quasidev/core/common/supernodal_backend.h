// The SparseFactor back end on the supernodal LDLᵀ of quasi_definite_ldlt.h (CHOLMOD's analysis,
// our numeric factorisation and solves), for a build with CHOLMOD. It factorises K
// (quasi_definite_factor.h), and M where the factor serves few solves
// (positive_definite_factor.h): there it takes half the time of CHOLMOD's own supernodal LLᵀ
// on the garments' systems (docs/solvers.md).
#pragma once

#include <memory>
#include <mutex>

#include "common/sparse_factor.h"

namespace qd::common {

struct SupernodalAnalysis;  // quasi_definite_ldlt.h

// The symbolic analysis kept for the factors of one pattern: the first supernodal factor to
// factorise fills it, the others take it (they may factorise at once, in a race's threads).
struct SharedAnalysis {
  std::mutex mutex;
  std::shared_ptr<const SupernodalAnalysis> supernodal;
};

// shared: where the analysis is kept (never null); positive: the factorisation fails unless
// every pivot is positive (the matrix is positive definite), else only when one vanishes.
std::unique_ptr<SparseFactor::Backend> supernodal_backend(std::shared_ptr<SharedAnalysis> shared,
                                                          bool positive);

}  // namespace qd::common
