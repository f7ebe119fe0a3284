// `quasidev batch ...`: the batch runs in the quasidev Python package (python/quasidev, with its
// local processes and Dask), so the command hands its arguments to `python -m quasidev batch`:
// the Python of $QD_PYTHON, else python3 on PATH. Replaces this process and returns only when
// that Python cannot be started (then with the exit status 2 and one error line).
#pragma once

namespace qd::cli {

int run_python_batch(int argc, char** argv);

}  // namespace qd::cli
