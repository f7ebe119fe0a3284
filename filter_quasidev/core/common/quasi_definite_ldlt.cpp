#include "common/quasi_definite_ldlt.h"

#include <cholmod.h>

#include <algorithm>
#include <cmath>

#include "common/error.h"

extern "C" {
void dgemm_(const char* ta, const char* tb, const int* m, const int* n, const int* k,
            const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
            const double* beta, double* c, const int* ldc);
void dtrsm_(const char* side, const char* uplo, const char* ta, const char* diag, const int* m,
            const int* n, const double* alpha, const double* a, const int* lda, double* b,
            const int* ldb);
}

namespace qd::common {
namespace {

constexpr int kUnblocked = QuasiDefiniteLdlt::kUnblocked;

// C(m×n) = beta·C − A(m×k)·B(n×k)ᵀ, column major.
void subtract_product(int m, int n, int k, const double* A, int lda, const double* B, int ldb,
                      double beta, double* C, int ldc) {
  const double minus_one = -1.0;
  dgemm_("N", "T", &m, &n, &k, &minus_one, A, &lda, B, &ldb, &beta, C, &ldc);
}

// B(m×n) := B·L⁻ᵀ for the unit lower triangle L(n×n).
void solve_right_unit_lower_transposed(int m, int n, const double* L, int ldl, double* B, int ldb) {
  const double one = 1.0;
  dtrsm_("R", "L", "T", "U", &m, &n, &one, L, &ldl, B, &ldb);
}

// Given B(m×n) = L21·D, with D on the diagonal of the factored block above it (leading
// dimension ld): W(m×n, leading dimension m) := L21·D and B := L21.
void split_off_diagonal(int m, int n, const double* factored, int ld, double* B, int ldb,
                        std::vector<double>& W) {
  W.resize(static_cast<size_t>(m) * static_cast<size_t>(n));
  for (int j = 0; j < n; ++j) {
    const double inverse = 1.0 / factored[j + static_cast<long>(j) * ld];
    double* b = B + static_cast<long>(j) * ldb;
    std::copy(b, b + m, W.begin() + static_cast<long>(j) * m);
    for (int i = 0; i < m; ++i) b[i] *= inverse;
  }
}

// A(n×n, lower triangle) = L·D·Lᵀ in place: unit L below the diagonal, D on it. The upper
// triangle is scratch. Recursive halving puts most of the work in dgemm. False when a pivot
// vanishes.
bool dense_ldlt(int n, double* A, int lda) {
  if (n <= kUnblocked) {
    for (int j = 0; j < n; ++j) {
      double* column = A + static_cast<long>(j) * lda;
      const double d = column[j];
      if (d == 0.0 || !std::isfinite(d)) return false;
      for (int k = j + 1; k < n; ++k) {  // A22 −= l·d·lᵀ, with l·d = the column before scaling
        const double wk = column[k];
        double* target = A + static_cast<long>(k) * lda;
        for (int i = k; i < n; ++i) target[i] -= column[i] * (wk / d);
      }
      for (int i = j + 1; i < n; ++i) column[i] /= d;
    }
    return true;
  }
  const int n1 = n / 2, n2 = n - n1;
  if (!dense_ldlt(n1, A, lda)) return false;
  double* A21 = A + n1;
  double* A22 = A + n1 + static_cast<long>(n1) * lda;
  solve_right_unit_lower_transposed(n2, n1, A, lda, A21, lda);  // A21 = L21·D1
  std::vector<double> W;
  split_off_diagonal(n2, n1, A, lda, A21, lda, W);
  subtract_product(n2, n2, n1, A21, lda, W.data(), n2, 1.0, A22, lda);  // A22 −= L21·D1·L21ᵀ
  return dense_ldlt(n2, A22, lda);
}

// cholmod_sparse view of a pattern in Eigen's column-major arrays (lower triangle).
cholmod_sparse pattern_view(int n, const int* outer, const int* inner) {
  cholmod_sparse A{};
  A.nrow = A.ncol = static_cast<size_t>(n);
  A.nzmax = static_cast<size_t>(outer[n]);
  A.p = const_cast<int*>(outer);
  A.i = const_cast<int*>(inner);
  A.stype = -1;
  A.itype = CHOLMOD_INT;
  A.xtype = CHOLMOD_PATTERN;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  return A;
}

// slot: each entry (i, j) of `lower` goes to row max and column min of (inverse[i], inverse[j]);
// entries are taken column by column of the factor, each supernode's rows mapped once. Entries
// above the diagonal (i < j) have no slot (−1): as CHOLMOD, the factor reads the lower triangle.
void place_entries(SupernodalAnalysis& an, const Eigen::SparseMatrix<double>& lower) {
  const int n = an.n;
  std::vector<int> inverse(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) inverse[static_cast<size_t>(an.perm[static_cast<size_t>(k)])] = k;
  std::vector<int> start(static_cast<size_t>(n) + 1, 0),
      entry(static_cast<size_t>(lower.nonZeros()));
  const auto column_of = [&](int j, int e) {
    return std::min(inverse[static_cast<size_t>(j)],
                    inverse[static_cast<size_t>(lower.innerIndexPtr()[e])]);
  };
  const auto upper = [&](int j, int e) { return lower.innerIndexPtr()[e] < j; };
  for (int j = 0; j < n; ++j)
    for (int e = lower.outerIndexPtr()[j]; e < lower.outerIndexPtr()[j + 1]; ++e)
      if (!upper(j, e)) ++start[static_cast<size_t>(column_of(j, e)) + 1];
  for (size_t k = 0; k < static_cast<size_t>(n); ++k) start[k + 1] += start[k];
  std::vector<int> next(start.begin(), start.end() - 1);
  for (int j = 0; j < n; ++j)
    for (int e = lower.outerIndexPtr()[j]; e < lower.outerIndexPtr()[j + 1]; ++e)
      if (!upper(j, e))
        entry[static_cast<size_t>(next[static_cast<size_t>(column_of(j, e))]++)] = e;
  std::vector<int> column_of_entry(entry.size());
  for (int j = 0; j < n; ++j)
    for (int e = lower.outerIndexPtr()[j]; e < lower.outerIndexPtr()[j + 1]; ++e)
      column_of_entry[static_cast<size_t>(e)] = j;
  an.slot.assign(entry.size(), -1);
  std::vector<int> map(static_cast<size_t>(n));
  for (size_t t = 0; t + 1 < an.super.size(); ++t) {
    const int height = an.row_start[t + 1] - an.row_start[t];
    for (int p = 0; p < height; ++p)
      map[static_cast<size_t>(an.rows[static_cast<size_t>(an.row_start[t] + p)])] = p;
    for (int k = an.super[t]; k < an.super[t + 1]; ++k)
      for (int q = start[static_cast<size_t>(k)]; q < start[static_cast<size_t>(k) + 1]; ++q) {
        const int e = entry[static_cast<size_t>(q)];
        const int a = inverse[static_cast<size_t>(lower.innerIndexPtr()[e])];
        const int b = inverse[static_cast<size_t>(column_of_entry[static_cast<size_t>(e)])];
        an.slot[static_cast<size_t>(e)] = an.value_start[t] +
                                          static_cast<long>(k - an.super[t]) * height +
                                          map[static_cast<size_t>(std::max(a, b))];
      }
  }
}

}  // namespace

std::shared_ptr<const SupernodalAnalysis> QuasiDefiniteLdlt::analyse(
    const Eigen::SparseMatrix<double>& lower) {
  auto an = std::make_shared<SupernodalAnalysis>();
  an->n = static_cast<int>(lower.rows());
  cholmod_common c;
  cholmod_start(&c);
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_NATURAL;  // then postordered, which keeps the fill
  c.supernodal = CHOLMOD_SUPERNODAL;
  cholmod_sparse A = pattern_view(an->n, lower.outerIndexPtr(), lower.innerIndexPtr());
  cholmod_factor* L = cholmod_analyze(&A, &c);
  if (!L || !L->is_super) {
    cholmod_free_factor(&L, &c);
    cholmod_finish(&c);
    throw Error("the sparse analysis of the deformation system failed (out of memory?)");
  }
  const auto copy = [](const void* p, size_t n) {
    const int* first = static_cast<const int*>(p);
    return std::vector<int>(first, first + n);
  };
  const size_t ns = L->nsuper;
  an->perm = copy(L->Perm, static_cast<size_t>(an->n));
  an->super = copy(L->super, ns + 1);
  an->row_start = copy(L->pi, ns + 1);
  an->rows = copy(L->s, static_cast<size_t>(an->row_start.back()));
  const std::vector<int> px = copy(L->px, ns + 1);
  an->value_start.assign(px.begin(), px.end());
  an->values = L->xsize;
  an->flops = c.fl;
  an->entries = c.lnz;
  cholmod_free_factor(&L, &c);
  cholmod_finish(&c);

  an->owner.resize(static_cast<size_t>(an->n));
  for (size_t s = 0; s < ns; ++s)
    std::fill(an->owner.begin() + an->super[s], an->owner.begin() + an->super[s + 1],
              static_cast<int>(s));
  place_entries(*an, lower);
  return an;
}

QuasiDefiniteLdlt::QuasiDefiniteLdlt(std::shared_ptr<const SupernodalAnalysis> analysis)
    : a_(std::move(analysis)), values_(a_->values) {}

bool QuasiDefiniteLdlt::factorize(const Eigen::SparseMatrix<double>& lower) {
  std::fill(values_.begin(), values_.end(), 0.0);
  const double* value = lower.valuePtr();
  for (size_t e = 0; e < a_->slot.size(); ++e)
    if (a_->slot[e] >= 0) values_[static_cast<size_t>(a_->slot[e])] += value[e];
  std::vector<double> work;
  std::vector<int> map(static_cast<size_t>(a_->n), -1);
  for (int s = 0; s + 1 < static_cast<int>(a_->super.size()); ++s)
    if (!factorize_supernode(s, work, map)) return false;
  return true;
}

// Supernode s, all of whose updates have arrived: LDLᵀ of its diagonal block, then its rows
// below (L21 = A21·L11⁻ᵀ·D⁻¹), then its update L21·D·L21ᵀ to the supernodes above.
bool QuasiDefiniteLdlt::factorize_supernode(int s, std::vector<double>& work,
                                            std::vector<int>& map) {
  const auto su = static_cast<size_t>(s);
  const int columns = a_->super[su + 1] - a_->super[su];
  const int height = a_->row_start[su + 1] - a_->row_start[su];
  const int below = height - columns;
  double* X = values_.data() + a_->value_start[su];
  if (!dense_ldlt(columns, X, height)) return false;
  if (below == 0) return true;
  double* X21 = X + columns;
  solve_right_unit_lower_transposed(below, columns, X, height, X21, height);  // L21·D
  std::vector<double> W;
  split_off_diagonal(below, columns, X, height, X21, height, W);
  update_ancestors(s, W.data(), work, map);
  return true;
}

// Subtracts L21·D·L21ᵀ (W = L21·D) from the supernodes that own the rows below s: for each run
// of rows owned by one supernode t, the block of columns of t is computed by one dgemm and
// scattered into t's panel through `map` (row → place in t's rows).
void QuasiDefiniteLdlt::update_ancestors(int s, const double* W, std::vector<double>& work,
                                         std::vector<int>& map) {
  const auto su = static_cast<size_t>(s);
  const int columns = a_->super[su + 1] - a_->super[su];
  const int height = a_->row_start[su + 1] - a_->row_start[su];
  const int below = height - columns;
  const int* row = a_->rows.data() + a_->row_start[su] + columns;
  const double* L21 = values_.data() + a_->value_start[su] + columns;
  std::vector<int> place;  // the places in t's rows of the rows from i on
  int mapped = -1;
  for (int i = 0; i < below;) {
    const int t = a_->owner[static_cast<size_t>(row[i])];
    int last = i;
    while (last < below && a_->owner[static_cast<size_t>(row[last])] == t &&
           last - i < kUpdateColumns)
      ++last;
    const auto tu = static_cast<size_t>(t);
    const int t_height = a_->row_start[tu + 1] - a_->row_start[tu];
    if (mapped != t) {
      for (int p = 0; p < t_height; ++p)
        map[static_cast<size_t>(a_->rows[static_cast<size_t>(a_->row_start[tu] + p)])] = p;
      mapped = t;
    }
    const int m = below - i, width = last - i;
    work.resize(static_cast<size_t>(m) * static_cast<size_t>(width));
    subtract_product(m, width, columns, W + i, below, L21 + i, height, 0.0, work.data(), m);  // −U
    place.resize(static_cast<size_t>(m));
    for (int k = 0; k < m; ++k)
      place[static_cast<size_t>(k)] = map[static_cast<size_t>(row[i + k])];
    for (int j = 0; j < width; ++j) {  // t's own rows come first: a row's place is its column
      double* target = values_.data() + a_->value_start[tu] +
                       static_cast<long>(place[static_cast<size_t>(j)]) * t_height;
      const double* u = work.data() + static_cast<long>(j) * m;
      for (int k = j; k < m; ++k) target[place[static_cast<size_t>(k)]] += u[k];
    }
    i = last;
  }
}

// Each supernode's rows of x are gathered into a dense block t (its rows × the right-hand
// sides), worked on there, and scattered back: the loops then run over contiguous memory, and
// the factor is read once for all right-hand sides.
Eigen::MatrixXd QuasiDefiniteLdlt::solve(const Eigen::MatrixXd& b) const {
  const Eigen::Index rhs = b.cols();
  Eigen::MatrixXd x(a_->n, rhs);
  for (int k = 0; k < a_->n; ++k) x.row(k) = b.row(a_->perm[static_cast<size_t>(k)]);
  const int ns = static_cast<int>(a_->super.size()) - 1;
  int tallest = 0;
  for (int s = 0; s < ns; ++s) tallest = std::max(tallest, panel(s).height);
  Eigen::MatrixXd block(tallest, rhs);
  const auto column = [](const Panel& p, int j) {  // L's column j below the diagonal
    return Eigen::Map<const Eigen::VectorXd>(p.X + static_cast<long>(j) * p.height + j + 1,
                                             p.height - j - 1);
  };
  for (int s = 0; s < ns; ++s) {  // L y = b, then D z = y
    const Panel p = panel(s);
    auto t = block.topRows(p.height);
    for (int i = 0; i < p.height; ++i) t.row(i) = x.row(p.row[i]);
    for (int j = 0; j < p.columns; ++j)
      t.bottomRows(p.height - j - 1).noalias() -= column(p, j) * t.row(j);
    for (int j = 0; j < p.columns; ++j)
      x.row(p.row[j]) = t.row(j) / p.X[j + static_cast<long>(j) * p.height];
    for (int i = p.columns; i < p.height; ++i) x.row(p.row[i]) = t.row(i);
  }
  for (int s = ns - 1; s >= 0; --s) {  // Lᵀ x = z
    const Panel p = panel(s);
    auto t = block.topRows(p.height);
    for (int i = 0; i < p.height; ++i) t.row(i) = x.row(p.row[i]);
    // One dot per right-hand side: on these short columns faster than a row times a block
    // (Eigen's matrix-vector product), 5–9 % of a 1M-triangle run (docs/solvers.md).
    for (int j = p.columns - 1; j >= 0; --j)
      for (Eigen::Index c = 0; c < rhs; ++c)
        t(j, c) -= column(p, j).dot(t.col(c).segment(j + 1, p.height - j - 1));
    for (int j = 0; j < p.columns; ++j) x.row(p.row[j]) = t.row(j);
  }
  Eigen::MatrixXd out(a_->n, rhs);
  for (int k = 0; k < a_->n; ++k) out.row(a_->perm[static_cast<size_t>(k)]) = x.row(k);
  return out;
}

bool QuasiDefiniteLdlt::pivots_positive() const {
  for (int s = 0; s + 1 < static_cast<int>(a_->super.size()); ++s) {
    const Panel p = panel(s);
    for (int j = 0; j < p.columns; ++j)
      if (!(p.X[j + static_cast<long>(j) * p.height] > 0)) return false;
  }
  return true;
}

int QuasiDefiniteLdlt::widest_supernode() const {
  int widest = 0;
  for (size_t s = 0; s + 1 < a_->super.size(); ++s)
    widest = std::max(widest, a_->super[s + 1] - a_->super[s]);
  return widest;
}

QuasiDefiniteLdlt::Panel QuasiDefiniteLdlt::panel(int s) const {
  const auto su = static_cast<size_t>(s);
  return {a_->super[su + 1] - a_->super[su], a_->row_start[su + 1] - a_->row_start[su],
          a_->rows.data() + a_->row_start[su], values_.data() + a_->value_start[su]};
}

}  // namespace qd::common
