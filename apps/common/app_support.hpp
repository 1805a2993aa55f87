#pragma once
/// What the command-line apps share: how they start MPI and Kokkos from the command line,
/// the exit-code convention, how errors are printed and end every MPI rank, and the peak
/// memory they report.

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

/// Seconds a rank that caught an exception waits for the others to report theirs before it
/// concludes that it failed alone and aborts the job.
constexpr double kErrorAgreementSeconds = 5.0;

/// Called by every rank that caught `e`; returns `code` or does not return. When every rank
/// caught an error (input validated the same way everywhere, a solver failure decided on
/// global norms), rank 0 prints it as "<program>: invalid input (n problems):" and one
/// problem a line, or "<program>: <message>", and every rank returns `code`. When this rank
/// failed alone (the others wait in a collective call that will never complete), it prints
/// "<program>: rank r of n: <message>" and ends every rank with MPI_Abort(`code`). Either
/// way an open RunFolder is moved to `<dir>.failed` with the message in its status first.
int report_error(const std::exception& e, int code, const std::string& program);

/// Collective, before a guarded body runs: the communicator the error handling agrees on.
void prepare_error_handling();

/// Runs `body` (returning an exit code) and maps the toolkit's exceptions to exit codes.
/// Every rank calls it at the same point.
template <class F> int run_guarded(const std::string& program, F&& body) {
  prepare_error_handling();
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

/// Peak resident memory of this process (VmHWM), MiB (2^20 bytes); 0 where /proc is not
/// available.
double peak_memory_mib();

} // namespace bipot::app
