#include "common/serial_libraries.h"

#include <dlfcn.h>

namespace qd::common {
namespace {

using GetCount = int (*)();
using SetCount = void (*)(int);

// An entry point of a library loaded in the process (OpenBLAS, libgomp), or null.
template <typename Function>
Function loaded(const char* name) {
  return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
}

}  // namespace

std::string loaded_blas_core() {
  const auto core_name = loaded<const char* (*)()>("openblas_get_corename");
  const char* name = core_name ? core_name() : nullptr;
  return name ? name : "";
}

void serial_openmp_in_this_thread() {
  static const auto set_levels = loaded<SetCount>("omp_set_max_active_levels");
  if (set_levels) set_levels(0);
}

SerialLibraries::SerialLibraries() {
  const auto get_blas = loaded<GetCount>("openblas_get_num_threads");
  const auto set_blas = loaded<SetCount>("openblas_set_num_threads");
  if (get_blas && set_blas) {
    saved_blas_threads_ = get_blas();
    set_blas(1);
    const auto stop_workers = loaded<void (*)()>("blas_thread_shutdown_");
    if (stop_workers) stop_workers();  // idle, they still spin; a threaded call restarts them
  }
  const auto get_levels = loaded<GetCount>("omp_get_max_active_levels");
  const auto set_levels = loaded<SetCount>("omp_set_max_active_levels");
  if (get_levels && set_levels) {
    saved_omp_levels_ = get_levels();
    set_levels(0);
  }
}

SerialLibraries::~SerialLibraries() {
  if (saved_blas_threads_ > 0) loaded<SetCount>("openblas_set_num_threads")(saved_blas_threads_);
  if (saved_omp_levels_ >= 0) loaded<SetCount>("omp_set_max_active_levels")(saved_omp_levels_);
}

}  // namespace qd::common
