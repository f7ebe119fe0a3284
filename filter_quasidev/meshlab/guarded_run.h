// Runs one filter's job and turns whatever it throws into the message the user reads: the
// engine's qd::Error verbatim (written for the user), running out of memory with what to try,
// anything else as an internal error to report.
#pragma once

#include <exception>
#include <new>
#include <string>

#include "common/error.h"

namespace qdml {

// Calls job(); returns "" when it returned, else the reason it failed.
template <typename Job>
std::string guarded_run(Job&& job) {
  try {
    job();
    return "";
  } catch (const qd::Error& error) {
    return error.what();
  } catch (const std::bad_alloc&) {
    return "out of memory: try a smaller mesh or split it into smaller patches";
  } catch (const std::exception& error) {
    return std::string("internal error (please report it with the mesh): ") + error.what();
  }
}

}  // namespace qdml
