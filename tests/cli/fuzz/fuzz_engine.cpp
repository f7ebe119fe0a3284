// Fuzz target of the engine (libFuzzer entry point): the bytes choose a small mesh (a height
// field on an n×n grid, n = 2..7, optionally with one face flipped), two patches split at a
// column, constrained vertices and parameters; qd::approximate must return a result of the right
// size or throw qd::common::Error — never crash, hang or produce NaN positions.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <utility>

#include "approximate/quasidev.h"
#include "common/error.h"

namespace {

using namespace qd::approximate;
using namespace qd::common;

// Reads bytes in order; zeros once they run out.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  unsigned next() { return pos_ < size_ ? data_[pos_++] : 0u; }
  double unit() { return next() / 255.0; }  // in [0, 1]

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

qd::approximate::Problem problem_from(ByteReader& in) {
  const int n = 2 + static_cast<int>(in.next() % 6);
  qd::approximate::Problem p;
  p.V.resize((n + 1) * (n + 1), 3);
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) p.V.row(y * (n + 1) + x) << x, y, 2 * in.unit() - 1;
  const unsigned flags = in.next();
  const int split =
      1 + static_cast<int>(in.next() % static_cast<unsigned>(n));  // patch seam column
  p.F.resize(2 * n * n, 3);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x, f = 2 * (y * n + x);
      p.F.row(f) << a, a + 1, a + n + 2;
      p.F.row(f + 1) << a, a + n + 2, a + n + 1;
      if (flags & 2) p.patch.insert(p.patch.end(), 2, x < split ? 0 : 1);
    }
  if ((flags & 65) == 65) std::swap(p.F(0, 0), p.F(0, 1));  // inconsistent orientation
  if (flags & 4)
    for (int v = 0; v < p.V.rows(); ++v)
      p.constrained.push_back(static_cast<char>(in.next() % 4 == 0));
  p.params.tolerance = 0.01 + 3 * in.unit();
  p.params.max_iter = 1 + static_cast<int>(in.next() % 4);
  p.params.weight = 1 + 60 * in.unit();
  p.params.anchor = 20 * in.unit();
  p.params.seams = (flags & 8) ? qd::approximate::SeamMode::Free : qd::approximate::SeamMode::Fixed;
  p.params.keep_boundary = (flags & 16) == 0;
  p.params.tolerance_mode =
      (flags & 32) ? qd::approximate::ToleranceMode::Total : qd::approximate::ToleranceMode::Step;
  p.params.targets = static_cast<qd::approximate::TargetMode>(in.next() % 3);
  return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  const qd::approximate::Problem problem = problem_from(in);
  try {
    const qd::approximate::Result r = qd::approximate::approximate(problem);
    if (r.V.rows() != problem.V.rows() || !r.V.allFinite()) std::abort();
  } catch (const qd::common::Error&) {
  }
  return 0;
}
