// Adds the wall-clock time of a scope, in milliseconds, to one StageTimes field.
#pragma once

#include <chrono>

namespace qd::common {

class StageTimer {
 public:
  explicit StageTimer(double& total_ms) : total_(total_ms), start_(Clock::now()) {}
  ~StageTimer() {
    total_ += std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
  }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  using Clock = std::chrono::steady_clock;
  double& total_;
  Clock::time_point start_;
};

}  // namespace qd::common
