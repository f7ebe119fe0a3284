// What one run of an adapter returns, and the two steps every adapter's run shares: running its
// job with whatever it throws turned into the message the user reads (the engine's
// qd::common::Error verbatim, running out of memory with what to try, anything else as an internal
// error to report), and handing the outcome to the filter table as a FilterRun.
#pragma once

#include <exception>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "common/error.h"
#include "filter_table.h"

namespace qdml {

template <typename Result>
struct RunOutcome {
  bool ok = false;
  std::string error;             // the reason, written for the user, when !ok
  std::vector<std::string> log;  // lines to log (also on failure: what was read from the mesh)
  Result result;                 // the engine's result when ok
};

// Calls job(outcome), which fills the log and the result; ok when it returned.
template <typename Result, typename Job>
RunOutcome<Result> guarded_run(Job&& job) {
  RunOutcome<Result> out;
  try {
    job(out);
    out.ok = true;
  } catch (const qd::common::Error& error) {
    out.error = error.what();
  } catch (const std::bad_alloc&) {
    out.error = "out of memory: try a smaller mesh or split it into smaller patches";
  } catch (const std::exception& error) {
    out.error = std::string("internal error (please report it with the mesh): ") + error.what();
  }
  return out;
}

// The outcome for the filter table: on success with figures(result) and what the run wrote.
template <typename Result, typename Figures>
FilterRun filter_run(RunOutcome<Result>&& outcome, Figures figures, std::vector<MeshPart> written) {
  FilterRun out;
  out.ok = outcome.ok;
  out.error = std::move(outcome.error);
  out.log = std::move(outcome.log);
  if (!out.ok) return out;
  out.figures = figures(outcome.result);
  out.written = std::move(written);
  return out;
}

}  // namespace qdml
