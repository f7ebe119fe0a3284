// OpenBLAS runs worker threads of its own. The engine runs its own threads (one patch per
// core, or the two scalar factors of a lone patch's iterative solve), so they would only contend
// (measured with bench/qd_bench: 100k triangles in 16 patches, engine 1.65 s with them, 0.48 s
// without), and their number would change the rounding of CHOLMOD's results. While a SerialBlas
// lives, OpenBLAS, if it is the BLAS of this process (CHOLMOD calls it), works in the calling
// thread only; the previous setting comes back afterwards, so a host such as MeshLab keeps its own.
#pragma once

namespace qd {

class SerialBlas {
 public:
  SerialBlas();
  ~SerialBlas();
  SerialBlas(const SerialBlas&) = delete;
  SerialBlas& operator=(const SerialBlas&) = delete;

 private:
  int saved_ = 0;  // OpenBLAS's thread count before, 0 when OpenBLAS is not loaded
};

}  // namespace qd
