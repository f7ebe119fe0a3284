#include "common/serial_blas.h"

#include <dlfcn.h>

namespace qd {
namespace {

using GetThreads = int (*)();
using SetThreads = void (*)(int);

// OpenBLAS's own entry points, looked up in the process (absent with another BLAS or none).
template <typename Function>
Function openblas(const char* name) {
  return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
}

}  // namespace

SerialBlas::SerialBlas() {
  const auto get = openblas<GetThreads>("openblas_get_num_threads");
  const auto set = openblas<SetThreads>("openblas_set_num_threads");
  if (!get || !set) return;
  saved_ = get();
  set(1);
}

SerialBlas::~SerialBlas() {
  if (saved_ > 0) openblas<SetThreads>("openblas_set_num_threads")(saved_);
}

}  // namespace qd
