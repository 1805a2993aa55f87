#pragma once
/// What the command-line apps share: the exit-code convention and how errors are printed,
/// and the peak memory they report.

#include "fem/core/error.hpp"

#include <exception>
#include <string>

namespace bipot::app {

/// Exit codes of every bipot app.
enum ExitCode { kOk = 0, kUsage = 1, kInvalidInput = 2, kSolverFailure = 3, kOtherError = 4 };

/// Prints `e` on rank 0 as "<program>: invalid input (n problems):" and one problem a line,
/// or "<program>: <message>"; returns `code`. Every rank calls it (each validated the input
/// the same way, so all fail before any collective call).
int report_error(const std::exception& e, int code, const std::string& program);

/// Runs `body` (returning an exit code) and maps the toolkit's exceptions to exit codes.
template <class F> int run_guarded(const std::string& program, F&& body) {
  try {
    return body();
  } catch (const InputError& e) {
    return report_error(e, kInvalidInput, program);
  } catch (const SolverError& e) {
    return report_error(e, kSolverFailure, program);
  } catch (const std::exception& e) {
    return report_error(e, kOtherError, program);
  }
}

/// Peak resident memory of this process (VmHWM), MB; 0 where /proc is not available.
double peak_memory_mb();

} // namespace bipot::app
