// The cost of adding face t to chart C in D-Charts' chart growing (Julius, Kraevoy, Sheffer 2005):
// the product F(C,t)^α · C(C,t)^β · P(C,t)^γ of
//   fitting      F = (δ/δmax)² + kFitFloor²: δ the face's deviation from C's cone (cone_proxy.h),
//                δmax the largest allowed. D-Charts measures it as (N·n_t − cos θ)², which is
//                flat near θ = 0 and would let a plane chart take curved faces cheaply; the angle
//                is the figure the user sets and the report gives. The floor lets shape decide
//                between faces that fit within a tenth of the limit.
//   compactness  C = π·D²/A(C): D the distance from C's seed to t, A(C) the chart's area;
//   boundary     P = outer/inner: the length of t's sides not shared with C over those shared,
//                so faces that straighten C's border go first.
// The heap compares the logarithm, which orders faces the same way and has no overflow.
#pragma once

#include <cmath>
#include <limits>

#include "segment/segment_params.h"

namespace qd::segment {

constexpr double kFitFloor = 0.1;

// log of w-th power of x, with 0^0 = 1 and log 0 = −∞.
inline double log_power(double x, double w) {
  if (w == 0) return 0.0;
  return x > 0 ? w * std::log(x) : -std::numeric_limits<double>::infinity();
}

inline double log_growing_cost(double deviation, double limit, double seed_distance,
                               double area_hint, double outer, double inner, const CostWeights& w) {
  const double r = deviation / limit;
  const double fit = r * r + kFitFloor * kFitFloor;
  const double compactness = M_PI * seed_distance * seed_distance / area_hint;
  const double boundary = outer / inner;
  return log_power(fit, w.fit) + log_power(compactness, w.compactness) +
         log_power(boundary, w.boundary);
}

}  // namespace qd::segment
