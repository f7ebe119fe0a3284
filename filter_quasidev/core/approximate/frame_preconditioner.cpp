#include "approximate/frame_preconditioner.h"

#include <cmath>

#include "approximate/common_names.h"
#include "common/parallel_for.h"

namespace qd::approximate {

FramePreconditioner::FramePreconditioner(const BlockPattern& pattern, SolverKind solver,
                                         int threads)
    : pattern_(pattern),
      threads_(static_cast<size_t>(threads)),
      K_n_(scalar_lower(pattern)),
      K_t_(K_n_),
      normal_(solver, Solves::AtOnce),
      tangent_(solver, Solves::AtOnce) {}

void FramePreconditioner::set_frames(const std::vector<Vec3>& normals) {
  frame_.resize(normals.size());
  for (size_t k = 0; k < normals.size(); ++k) {
    const double length = normals[k].norm();
    const Vec3 nu = length > 0 ? Vec3(normals[k] / length) : Vec3::UnitZ();
    const Vec3 away = std::abs(nu.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    const Vec3 t1 = nu.cross(away).normalized();
    frame_[k].row(0) = nu.transpose();
    frame_[k].row(1) = t1.transpose();
    frame_[k].row(2) = nu.cross(t1).transpose();
  }
}

void FramePreconditioner::restrict_to_frames(const Eigen::SparseMatrix<double>& M) {
  const double* value = M.valuePtr();
  const int* outer = M.outerIndexPtr();
  double* kn = K_n_.valuePtr();
  double* kt = K_t_.valuePtr();
  // a_rᵀ B a_k and ½ Σ t_rᵀ B t_k for block B between blocks r and k.
  const auto restrict = [&](const Eigen::Matrix3d& B, int r, int k, int at) {
    const Eigen::Matrix3d R =
        frame_[static_cast<size_t>(r)] * B * frame_[static_cast<size_t>(k)].transpose();
    kn[at] = R(0, 0);
    kt[at] = 0.5 * (R(1, 1) + R(2, 2));
  };
  parallel_ranges(static_cast<size_t>(pattern_.blocks()), threads_, kRangeChunk,
                  [&](size_t first, size_t last) {
                    for (int k = static_cast<int>(first); k < static_cast<int>(last); ++k) {
                      Eigen::Matrix3d B;
                      for (int j = 0; j < 3; ++j)
                        for (int i = j; i < 3; ++i)
                          B(i, j) = B(j, i) = value[diagonal_entry(outer, k, i, j)];
                      restrict(B, k, k, K_n_.outerIndexPtr()[k]);
                      for (int s = pattern_.begin(k); s < pattern_.end(k); ++s) {
                        for (int j = 0; j < 3; ++j)
                          for (int i = 0; i < 3; ++i)
                            B(i, j) = value[block_entry(outer, pattern_, k, s, i, j)];
                        restrict(B, pattern_.row(s), k,
                                 K_n_.outerIndexPtr()[k] + 1 + s - pattern_.begin(k));
                      }
                    }
                  });
}

void FramePreconditioner::build(const Eigen::SparseMatrix<double>& M,
                                const std::vector<Vec3>& normals) {
  set_frames(normals);
  restrict_to_frames(M);
  parallel_for(2, threads_, [&](size_t i) {
    if (i == 0)
      normal_.factorize(K_n_);
    else
      tangent_.factorize(K_t_);
  });
}

Eigen::VectorXd FramePreconditioner::apply(const Eigen::VectorXd& r) const {
  const Eigen::Index n = static_cast<Eigen::Index>(frame_.size());
  Eigen::VectorXd normal(n);
  Eigen::MatrixXd tangent(n, 2);
  const auto each_block = [&](const auto& work) {
    parallel_ranges(static_cast<size_t>(n), threads_, kRangeChunk, [&](size_t first, size_t last) {
      for (auto k = static_cast<Eigen::Index>(first); k < static_cast<Eigen::Index>(last); ++k)
        work(k);
    });
  };
  each_block([&](Eigen::Index k) {
    const Vec3 c = frame_[static_cast<size_t>(k)] * r.segment<3>(3 * k);
    normal[k] = c[0];
    tangent(k, 0) = c[1];
    tangent(k, 1) = c[2];
  });
  Eigen::VectorXd zn;
  Eigen::MatrixXd zt;
  parallel_for(2, threads_, [&](size_t i) {
    if (i == 0)
      zn = normal_.solve(normal);
    else
      zt = tangent_.solve(tangent);
  });
  Eigen::VectorXd z(r.size());
  each_block([&](Eigen::Index k) {
    z.segment<3>(3 * k) =
        frame_[static_cast<size_t>(k)].transpose() * Vec3(zn[k], zt(k, 0), zt(k, 1));
  });
  return z;
}

}  // namespace qd::approximate
