#include "flatten/symmetric_pieces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace qd::flatten {

namespace {

const double kMaxTurn = 5 * M_PI / 180;  // the largest turn the fit may add, radians
const int kSamplesPerSize = 512;         // sew lines are sampled at most size/512 apart
const int kFitSamples = 128;             // samples of the member the closest-point fit uses
const int kFitIterations = 30;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// A piece as the matcher sees it.
struct Shape {
  std::vector<Outline> outlines;
  double area = 0;                                     // of the region: outer loop minus holes
  double perimeter = 0;                                // of every loop
  double size = 0;                                     // diagonal of the bounding box
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();  // of the region's area
  std::vector<Eigen::Vector2d> samples;                // along the sew lines, dense
};

Shape shape_of(const PatternPiece& piece) {
  Shape s;
  s.outlines = piece.outlines;
  Eigen::AlignedBox2d box;
  std::vector<double> areas;
  std::vector<Eigen::Vector2d> moments;  // per loop: signed area × centroid
  for (const Outline& loop : piece.outlines) {
    double a = 0;
    Eigen::Vector2d m = Eigen::Vector2d::Zero();
    for (size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector2d &p = loop[i], &q = loop[(i + 1) % loop.size()];
      a += cross(p, q) / 2;
      m += cross(p, q) * (p + q) / 6;
      s.perimeter += (q - p).norm();
      box.extend(p);
    }
    areas.push_back(a);
    moments.push_back(m);
  }
  if (areas.empty()) return s;
  s.size = box.diagonal().norm();
  // The outer loop encloses the most area; holes subtract, whatever their orientation.
  const size_t outer = static_cast<size_t>(
      std::max_element(areas.begin(), areas.end(),
                       [](double a, double b) { return std::abs(a) < std::abs(b); }) -
      areas.begin());
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  for (size_t k = 0; k < areas.size(); ++k) {
    const double sign = (k == outer ? 1.0 : -1.0) * (areas[k] < 0 ? -1.0 : 1.0);
    s.area += sign * areas[k];
    moment += sign * moments[k];
  }
  s.centroid = s.area > 0 ? Eigen::Vector2d(moment / s.area) : box.center();
  const double spacing = s.size / kSamplesPerSize;
  for (const Outline& loop : piece.outlines)
    for (size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector2d &p = loop[i], &q = loop[(i + 1) % loop.size()];
      const int steps = std::max(1, static_cast<int>(std::ceil((q - p).norm() / spacing)));
      for (int j = 0; j < steps; ++j) s.samples.push_back(p + (q - p) * j / steps);
    }
  return s;
}

// x ↦ A·x + t
struct Motion {
  Eigen::Matrix2d A;
  Eigen::Vector2d t;
  Eigen::Vector2d operator()(const Eigen::Vector2d& x) const { return A * x + t; }
};

Eigen::Vector2d closest_on_segment(const Eigen::Vector2d& x, const Eigen::Vector2d& p,
                                   const Eigen::Vector2d& q) {
  const Eigen::Vector2d d = q - p;
  const double len2 = d.squaredNorm();
  return p + (len2 > 0 ? std::clamp((x - p).dot(d) / len2, 0.0, 1.0) : 0.0) * d;
}

// The point of the outlines closest to x.
Eigen::Vector2d closest_on_outlines(const Eigen::Vector2d& x,
                                    const std::vector<Outline>& outlines) {
  Eigen::Vector2d best = x;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (const Outline& loop : outlines)
    for (size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector2d c = closest_on_segment(x, loop[i], loop[(i + 1) % loop.size()]);
      if ((c - x).squaredNorm() < best_d2) {
        best_d2 = (c - x).squaredNorm();
        best = c;
      }
    }
  return best;
}

// The largest distance of a moved point to the outlines; stops early above `limit`.
double farthest(const std::vector<Eigen::Vector2d>& points, const Motion& move,
                const std::vector<Outline>& outlines, double limit) {
  double worst = 0;
  for (const Eigen::Vector2d& x : points) {
    const Eigen::Vector2d at = move(x);
    worst = std::max(worst, (closest_on_outlines(at, outlines) - at).norm());
    if (worst > limit) break;
  }
  return worst;
}

// Symmetric Hausdorff distance of the sew lines of `rep` and of `member` moved; stops early
// above `limit`.
double hausdorff(const Shape& rep, const Shape& member, const Motion& move, double limit) {
  double d = farthest(member.samples, move, rep.outlines, limit);
  if (d > limit) return d;
  const Motion back{move.A.inverse(), -move.A.inverse() * move.t};
  return std::max(d, farthest(rep.samples, back, member.outlines, limit));
}

// Refines `L` (a symmetry of the sheet's frame, centroid onto centroid) by iterative closest
// points: Procrustes rotation and translation of member samples onto their closest points on the
// rep's sew lines,
// the added turn limited to kMaxTurn.
Motion refine(const Shape& rep, const Shape& member, const Eigen::Matrix2d& L) {
  std::vector<Eigen::Vector2d> y;  // member samples, symmetry applied, centroid at the origin
  const size_t stride = std::max<size_t>(1, member.samples.size() / kFitSamples);
  for (size_t i = 0; i < member.samples.size(); i += stride)
    y.push_back(L * (member.samples[i] - member.centroid));
  const Eigen::Vector2d y_mean =
      std::accumulate(y.begin(), y.end(), Eigen::Vector2d(Eigen::Vector2d::Zero())) / y.size();
  Eigen::Rotation2Dd turn(0);
  Eigen::Vector2d shift = rep.centroid;
  for (int iteration = 0; iteration < kFitIterations; ++iteration) {
    Eigen::Vector2d q_mean = Eigen::Vector2d::Zero();
    std::vector<Eigen::Vector2d> q;
    for (const Eigen::Vector2d& yi : y) {
      q.push_back(closest_on_outlines(turn * yi + shift, rep.outlines));
      q_mean += q.back();
    }
    q_mean /= static_cast<double>(q.size());
    double sin_sum = 0, cos_sum = 0;
    for (size_t i = 0; i < y.size(); ++i) {
      sin_sum += cross(y[i] - y_mean, q[i] - q_mean);
      cos_sum += (y[i] - y_mean).dot(q[i] - q_mean);
    }
    const Eigen::Rotation2Dd next(std::clamp(std::atan2(sin_sum, cos_sum), -kMaxTurn, kMaxTurn));
    const Eigen::Vector2d next_shift = q_mean - (next * y_mean);
    const bool settled = std::abs(next.angle() - turn.angle()) < 1e-12 &&
                         (next_shift - shift).norm() < 1e-12 * rep.size;
    turn = next;
    shift = next_shift;
    if (settled) break;
  }
  const Eigen::Matrix2d A = turn.toRotationMatrix() * L;
  return {A, shift - A * member.centroid};
}

struct Fit {
  bool fits = false;
  bool mirrored = false;
  double distance = 0;
};

// How `member` best fits `rep` within `limit` (a length): unmirrored alignments first.
Fit best_fit(const Shape& rep, const Shape& member, double limit) {
  Fit fit;
  if (limit <= 0 || rep.outlines.size() != member.outlines.size()) return fit;
  if (std::abs(rep.area - member.area) > 2 * limit * (rep.perimeter + member.perimeter)) return fit;
  // Identity, 180° rotation, then the mirrors x → −x and y → −y.
  const Eigen::Matrix2d symmetries[] = {
      Eigen::Vector2d(1, 1).asDiagonal(), Eigen::Vector2d(-1, -1).asDiagonal(),
      Eigen::Vector2d(-1, 1).asDiagonal(), Eigen::Vector2d(1, -1).asDiagonal()};
  const double unrefined_limit = limit + std::sin(kMaxTurn) * std::max(rep.size, member.size);
  for (int k = 0; k < 4; ++k) {
    const bool mirrored = k >= 2;
    if (fit.fits && mirrored) break;
    const Eigen::Matrix2d& L = symmetries[k];
    const Motion unrefined{L, rep.centroid - L * member.centroid};
    const double d0 = hausdorff(rep, member, unrefined, unrefined_limit);
    if (d0 > unrefined_limit) continue;
    const double d = std::min(d0, hausdorff(rep, member, refine(rep, member, L), limit));
    if (d <= limit && (!fit.fits || d < fit.distance)) fit = {true, mirrored, d};
  }
  return fit;
}

}  // namespace

std::vector<PieceGroup> symmetric_groups(const std::vector<PatternPiece>& pieces,
                                         double tolerance) {
  if (pieces.size() > kMaxSymmetryPieces) tolerance = 0;
  std::vector<PieceGroup> groups;
  if (tolerance <= 0) {
    for (int m = 0; m < static_cast<int>(pieces.size()); ++m) groups.push_back({{m}, {0}, 0});
    return groups;
  }
  std::vector<Shape> shapes;
  for (const PatternPiece& p : pieces) shapes.push_back(shape_of(p));
  // Each piece in turn joins the representative it fits best (the smallest difference, the
  // earliest on a tie), or else represents a new group.
  for (int m = 0; m < static_cast<int>(pieces.size()); ++m) {
    PieceGroup* chosen = nullptr;
    Fit chosen_fit;
    double chosen_difference = 0;
    for (PieceGroup& group : groups) {
      const Shape& rep = shapes[group.members[0]];
      const Fit fit = best_fit(rep, shapes[m], tolerance / 100 * rep.size);
      const double difference = fit.fits ? 100 * fit.distance / rep.size : 0;
      if (fit.fits && (!chosen || difference < chosen_difference)) {
        chosen = &group;
        chosen_fit = fit;
        chosen_difference = difference;
      }
    }
    if (!chosen) {
      groups.push_back({{m}, {0}, 0});
      continue;
    }
    chosen->members.push_back(m);
    chosen->mirrored.push_back(chosen_fit.mirrored);
    chosen->difference = std::max(chosen->difference, chosen_difference);
  }
  return groups;
}

}  // namespace qd::flatten
