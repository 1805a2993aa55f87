#pragma once
/// What the command-line apps share: how they start MPI and Kokkos from the command line,
/// the exit-code convention and how errors are printed, and the peak memory they report.

#include "fem/core/error.hpp"

#include <exception>
#include <memory>
#include <string>
#include <vector>

namespace bipot {
class ParallelEnvironment;
}

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

/// Starts MPI and Kokkos (a ParallelEnvironment) with the command line's --kokkos-* options
/// only, each checked first: Kokkos would also take the app's --help and its unprefixed
/// aliases (--threads=...), and a malformed value makes it throw from its initialisation,
/// which aborts the process. `args` receives the other arguments (argv[0] excluded). Returns
/// nullptr after printing "<program>: ..." to stderr if an option is malformed or unknown or
/// Kokkos does not start; the caller then exits with kUsage.
std::unique_ptr<ParallelEnvironment>
start_parallel(int argc, char** argv, const std::string& program, std::vector<std::string>& args);

/// Peak resident memory of this process (VmHWM), MB; 0 where /proc is not available.
double peak_memory_mb();

} // namespace bipot::app
