#include "python_batch.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace qd::cli {
namespace {

// Runs the package's batch, or says which Python lacks the package and what to do.
constexpr const char* kLauncher =
    "import sys\n"
    "try:\n"
    "    from quasidev.__main__ import main\n"
    "except ImportError as e:\n"
    "    sys.exit(f'quasidev: error: the batch runs in the quasidev Python package, which '\n"
    "             f'{sys.executable} cannot import ({e}): run `pip install .` in the '\n"
    "             'repository, or set QD_PYTHON to a Python that has it')\n"
    "sys.exit(main(sys.argv[1:]))\n";

}  // namespace

int run_python_batch(int argc, char** argv) {
  const char* chosen = std::getenv("QD_PYTHON");
  const std::string python = chosen && *chosen ? chosen : "python3";
  std::vector<std::string> args = {python, "-c", kLauncher};
  for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);  // "batch" and its arguments
  std::vector<char*> pointers;
  for (std::string& a : args) pointers.push_back(a.data());
  pointers.push_back(nullptr);
  execvp(pointers[0], pointers.data());
  std::cerr << "quasidev: error: cannot start " << python << " for `quasidev batch` ("
            << std::strerror(errno) << "): install Python 3 or set QD_PYTHON" << std::endl;
  return 2;
}

}  // namespace qd::cli
