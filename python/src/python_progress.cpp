#include "python_progress.h"

#include <algorithm>
#include <utility>

namespace qd::python {

PythonProgress::PythonProgress(nb::object callable) : callable_(std::move(callable)) {}

common::Progress PythonProgress::callback() {
  if (callable_.is_none()) return {};
  return [this](int percent, const std::string&) {
    percent = std::clamp(percent, 0, 100);
    if (error_ || percent <= last_percent_) return;
    last_percent_ = percent;
    nb::gil_scoped_acquire gil;
    try {
      callable_(percent / 100.0);
    } catch (nb::python_error& e) {
      error_ = std::make_unique<nb::python_error>(std::move(e));
    }
  };
}

void PythonProgress::rethrow() {
  if (error_) {
    nb::python_error e = std::move(*error_);
    error_.reset();
    throw e;
  }
}

}  // namespace qd::python
