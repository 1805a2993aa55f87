#pragma once
/// The folder a run writes its results into, so that a failing run never spoils the results
/// of the good run before it. A run writes into a fresh sibling `<dir>.running-<pid>`; on
/// success finish() moves it into place as `<dir>` (the old results are removed only once
/// the new ones are there); on failure the run's converged increments go to `<dir>.failed`
/// and `<dir>` is left as it was. Each folder holds a `status.txt` (YAML): `status:` is
/// `running`, `finished` or `failed`, a failure with the stage, the step and the message.
/// Rank 0 does the file-system work; the other ranks wait at a barrier.

#include "fem/analysis/static_analysis.hpp"
#include "fem/input/problem_spec.hpp"

#include <string>
#include <vector>

namespace bipot::app {

class RunFolder {
public:
  /// Collective, before anything is solved: rank 0 checks that `directory` can be written
  /// (created, or replaced when it holds the results of an earlier run) and creates the
  /// working folder with status `running`; on any problem every rank throws Error naming the
  /// path. The status names `program` and the input file; `spec`'s stages name a failure.
  /// The folder stays open (see fail_open_run_folder()) until finish().
  RunFolder(const std::string& directory, const ProblemSpec& spec, const std::string& program);

  /// Where the results are written until finish().
  const std::string& working() const { return working_; }
  /// Where they end up (`directory` as given).
  const std::string& directory() const { return directory_; }

  /// After each converged increment, on every rank: a failure is reported as the next one.
  void converged(const StepReport& report);

  /// Collective: status `finished`, then the working folder becomes `directory`. Throws Error
  /// on every rank if the move fails (the results then stay in working()).
  void finish();

private:
  std::string directory_, working_;
};

/// Why a run could not write its results into `directory`, or "": the checks RunFolder's
/// constructor makes before it creates anything — a named folder that does not contain the
/// current directory, missing or empty or holding an earlier run's results (so does
/// `<directory>.failed`), whose nearest existing parent is a folder this process may write
/// into. `bipot check` reports the same problem at `output.directory`.
std::string results_folder_problem(const std::string& directory);

/// The error handling's side of RunFolder: if a run folder is open on this rank, writes
/// status `failed` (the increment after the last converged one, and `message`) into it, and
/// when `details` is not empty (the whole residual history of IncrementFailure) writes
/// `message` and `details` to `failure.log` beside it; moves the folder to `<dir>.failed`
/// (replacing an older one) and returns a sentence saying where the converged increments
/// (and failure.log) are; "" when no folder was open. Never throws. Called on rank 0 when
/// every rank failed, or on the failing rank when it failed alone.
std::string fail_open_run_folder(const std::string& message, const std::string& details = "");

} // namespace bipot::app
