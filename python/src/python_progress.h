// The engine's progress reports passed on to a Python callable as a fraction 0..1 that never
// decreases, with the GIL held during the call. An exception the callable raises is kept, no
// later report is passed on, and rethrow() raises it once the engine has returned.
#pragma once

#include <nanobind/nanobind.h>

#include <memory>
#include <utility>

#include "common/progress.h"

namespace qd::python {

namespace nb = nanobind;

class PythonProgress {
 public:
  explicit PythonProgress(nb::object callable);
  // The engine's callback (empty when there is no callable); valid while this object lives.
  common::Progress callback();
  // Raises the exception the callable raised, if it did. Call with the GIL held.
  void rethrow();

 private:
  nb::object callable_;
  int last_percent_ = -1;
  std::unique_ptr<nb::python_error> error_;
};

// run(progress)'s result, run with the GIL released and its progress passed on to `callable`
// (None: no reports); raises what the callable raised once run has returned.
template <typename Run>
auto run_without_gil(nb::object callable, Run run) {
  PythonProgress progress(std::move(callable));
  decltype(run(common::Progress{})) result;
  {
    nb::gil_scoped_release released;
    result = run(progress.callback());
  }
  progress.rethrow();
  return result;
}

}  // namespace qd::python
