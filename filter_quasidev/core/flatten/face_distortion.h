// How one face's 3D→2D map distorts it (docs/design.md "Metrics", Flattening): the singular values
// σ1 ≥ σ2 of its 2×2 Jacobian J (flat_triangles.h) are the largest and smallest stretch of any
// direction in the face; 1 and 1 for an isometry.
#pragma once

#include <Eigen/Core>

namespace qd::flatten {

struct Stretch {
  double s1 = 1, s2 = 1;  // σ1 ≥ σ2 ≥ 0
  bool flipped = false;   // det J ≤ 0: the face is mirrored or collapsed
};

// Closed-form SVD of a 2×2 matrix: with E = (J00 + J11)/2, H = (J10 − J01)/2, F = (J00 − J11)/2,
// G = (J10 + J01)/2, the singular values are √(E² + H²) ± √(F² + G²) (up to sign), and
// det J = (E² + H²) − (F² + G²).
Stretch stretch(const Eigen::Matrix2d& J);

// Length distortion max(σ1 − 1, 1 − σ2): the worst relative change of a length in the face.
double length_distortion(const Stretch& s);

// The per-face quality the adapters show: σ1 − 1, or −(1 − σ2) where compression is the larger
// of the two (σ2 < 1 and 1 − σ2 > σ1 − 1), so stretched faces read positive, squeezed negative.
double signed_stretch(const Stretch& s);

}  // namespace qd::flatten
