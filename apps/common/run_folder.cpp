#include "apps/common/run_folder.hpp"

#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <optional>
#include <unistd.h>

namespace bipot::app {

namespace fs = std::filesystem;

namespace {

constexpr const char* kStatusFile = "status.txt";
constexpr const char* kFailureLog = "failure.log";

// The run whose folder is open on this rank: between RunFolder's constructor and finish(),
// for the error handling, which runs after the stack (and the RunFolder) has unwound.
struct OpenRun {
  fs::path target, working;
  std::string program, input, started;
  std::vector<std::string> stages;
  int ranks = 1;
  bool any_step = false;
  StepReport last;
};
std::optional<OpenRun> open_run;

std::string now() {
  const std::time_t t = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", std::localtime(&t));
  return text;
}

// A YAML double-quoted scalar.
std::string yaml_quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c == '\n' ? ' ' : c;
  }
  return out + "\"";
}

fs::path failed_folder(const fs::path& target) {
  return fs::path(target.string() + ".failed");
}

// Writes `folder`/status.txt through a temporary file and rename(), so that it is never
// half written. `message`, when not empty, is a YAML literal block.
void write_status(const OpenRun& run, const fs::path& folder, const std::string& status,
                  const std::vector<std::pair<std::string, std::string>>& fields,
                  const std::string& message = "") {
  const fs::path file = folder / kStatusFile, tmp = folder / (std::string(kStatusFile) + ".tmp");
  {
    std::ofstream out(tmp);
    out << "status: " << status << "\n"
        << "program: " << run.program << "\n"
        << "input: " << yaml_quoted(run.input) << "\n"
        << "ranks: " << run.ranks << "\n"
        << "started: " << yaml_quoted(run.started) << "\n";
    for (const auto& [key, value] : fields)
      out << key << ": " << value << "\n";
    if (!message.empty()) {
      out << "message: |\n";
      std::size_t start = 0;
      while (start <= message.size()) {
        const std::size_t end = std::min(message.find('\n', start), message.size());
        out << "  " << message.substr(start, end - start) << "\n";
        start = end + 1;
      }
    }
    out.close();
    if (!out) throw Error("cannot write '" + tmp.string() + "'");
  }
  fs::rename(tmp, file);
}

// Why `folder` may not be replaced or removed by a run, or "": it must be missing, empty or a
// folder a run wrote (with its status.txt), so that a mistyped output directory never costs
// unrelated files.
std::string foreign(const fs::path& folder) {
  std::error_code ec;
  if (!fs::exists(folder, ec)) return "";
  if (!fs::is_directory(folder, ec)) return "'" + folder.string() + "' exists and is not a folder";
  if (fs::is_empty(folder, ec) || fs::exists(folder / kStatusFile, ec)) {
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
      return "cannot replace '" + folder.string() + "': " + std::strerror(errno);
    return "";
  }
  return "'" + folder.string() +
         "' holds files that no bipot run wrote (no status.txt; an older bipot wrote none): "
         "remove it or choose another output directory";
}

} // namespace

std::string results_folder_problem(const std::string& directory) {
  fs::path target = fs::path(directory).lexically_normal();
  if (!target.has_filename() && target.has_parent_path())
    target = target.parent_path(); // "results/" names the folder results
  if (!target.has_filename() || target.filename() == "." || target.filename() == "..")
    return "'" + target.string() + "' cannot be a results folder (name it, e.g. results/run)";
  std::error_code ec;
  const fs::path absolute = fs::absolute(target, ec).lexically_normal();
  const fs::path cwd = fs::current_path(ec);
  const auto [end, rest] = std::mismatch(absolute.begin(), absolute.end(), cwd.begin(), cwd.end());
  if (end == absolute.end())
    return "'" + target.string() + "' contains the current directory: choose a subfolder";
  for (const fs::path& folder : {target, failed_folder(target)}) {
    const std::string problem = foreign(folder);
    if (!problem.empty()) return problem;
  }
  // The parent folders a run would create: the nearest that exists must be a folder this
  // process may create entries in.
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  fs::path existing = parent;
  while (!fs::exists(existing, ec) && existing.has_parent_path() &&
         existing.parent_path() != existing)
    existing = existing.parent_path();
  if (!fs::exists(existing, ec)) existing = ".";
  if (!fs::is_directory(existing, ec))
    return "cannot create '" + parent.string() + "' (" +
           (existing == parent ? std::string("a file of that name exists")
                               : "'" + existing.string() + "' is a file") +
           ")";
  if (::access(existing.c_str(), W_OK | X_OK) != 0)
    return "cannot create '" + (existing == parent ? target : parent).string() + "' in '" +
           existing.string() + "': " + std::strerror(errno);
  return "";
}

namespace {

// Rank 0: checks the target (results_folder_problem) and creates the working folder; returns
// the problem, or "".
std::string open_working_folder(OpenRun& run) {
  const fs::path target = run.target;
  std::string problem = results_folder_problem(target.string());
  if (!problem.empty()) return problem;
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) return "cannot create '" + parent.string() + "': " + ec.message();
  run.working = fs::path(target.string() + ".running-" + std::to_string(::getpid()));
  fs::remove_all(run.working, ec); // a leftover of an earlier process with the same id
  if (!fs::create_directory(run.working, ec))
    return "cannot create '" + run.working.string() +
           "': " + (ec ? ec.message() : std::string("it exists"));
  try {
    write_status(run, run.working, "running", {});
  } catch (const std::exception& e) {
    fs::remove_all(run.working, ec);
    return e.what();
  }
  return "";
}

std::string step_text(const StepReport& r) {
  return yaml_quoted("stage " + r.stage + ", step " + std::to_string(r.step));
}

// Rank 0: the working folder replaces the target. rename(2) cannot replace a non-empty
// folder, so an existing one is swapped with the new (renameat2 RENAME_EXCHANGE, atomic) or,
// where the file system cannot swap, renamed aside first; the old results are removed last.
void move_into_place(const fs::path& working, const fs::path& target) {
  std::error_code ec;
  if (!fs::exists(target, ec)) {
    fs::rename(working, target);
    return;
  }
  if (::renameat2(AT_FDCWD, working.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) {
    fs::remove_all(working); // now the old results
    return;
  }
  const fs::path old = fs::path(working.string() + ".old");
  fs::rename(target, old);
  fs::rename(working, target);
  fs::remove_all(old);
}

} // namespace

RunFolder::RunFolder(const std::string& directory, const ProblemSpec& spec,
                     const std::string& program)
    : directory_(directory) {
  OpenRun run;
  run.target = fs::path(directory).lexically_normal();
  if (!run.target.has_filename() && run.target.has_parent_path())
    run.target = run.target.parent_path(); // "results/" names the folder results
  run.program = program;
  run.input = spec.file;
  run.started = now();
  for (const auto& stage : spec.stages)
    run.stages.push_back(stage.name);
  run.ranks = mpi_size();
  std::string problem, working;
  if (mpi_rank() == 0) {
    problem = open_working_folder(run);
    working = run.working.string();
  }
  broadcast(problem, 0);
  if (!problem.empty()) throw Error("cannot write the results: " + problem);
  broadcast(working, 0);
  run.working = working;
  working_ = working;
  open_run = std::move(run);
}

void RunFolder::converged(const StepReport& report) {
  if (!open_run) return;
  open_run->any_step = true;
  open_run->last = report;
}

void RunFolder::finish() {
  barrier(); // every rank has written its part
  std::string problem;
  if (mpi_rank() == 0 && open_run) {
    try {
      const OpenRun& run = *open_run;
      std::vector<std::pair<std::string, std::string>> fields = {
          {"ended", yaml_quoted(now())},
          {"converged_increments", std::to_string(run.any_step ? run.last.global_step : 0)}};
      if (run.any_step) fields.push_back({"last_converged", step_text(run.last)});
      write_status(run, run.working, "finished", fields);
      move_into_place(run.working, run.target);
    } catch (const std::exception& e) {
      problem = e.what();
    }
  }
  broadcast(problem, 0);
  if (!problem.empty())
    throw Error("cannot move the results from '" + working_ + "' to '" + directory_ +
                "': " + problem);
  open_run.reset();
}

std::string fail_open_run_folder(const std::string& message, const std::string& details) {
  if (!open_run) return "";
  const OpenRun run = std::move(*open_run);
  open_run.reset();
  std::string stage, step;
  const StepReport& last = run.last;
  const int next_stage = last.stage_index + 1;
  if (!run.any_step) {
    stage = run.stages.empty() ? "" : run.stages.front();
    step = "1";
  } else if (last.load_factor < 1.0 - 1e-12) {
    stage = last.stage;
    step = std::to_string(last.step + 1);
  } else if (next_stage < static_cast<int>(run.stages.size())) {
    stage = run.stages[next_stage];
    step = "1";
  } else {
    stage = "after the last increment";
    step = "none";
  }
  std::vector<std::pair<std::string, std::string>> fields = {
      {"ended", yaml_quoted(now())},
      {"stage", yaml_quoted(stage)},
      {"step", step},
      {"converged_increments", std::to_string(run.any_step ? last.global_step : 0)}};
  if (run.any_step) fields.push_back({"last_converged", step_text(last)});
  const fs::path failed = failed_folder(run.target);
  try {
    write_status(run, run.working, "failed", fields, message);
    if (!details.empty()) {
      std::ofstream log(run.working / kFailureLog);
      log << message << "\n\n" << details;
      if (details.back() != '\n') log << "\n";
    }
    fs::remove_all(failed);
    fs::rename(run.working, failed);
  } catch (const std::exception& e) {
    return "this run's converged increments are in " + run.working.string() + " (" + e.what() + ")";
  }
  std::error_code ec;
  std::string where = run.any_step ? "this run's converged increments are in " + failed.string() +
                                         " (see its " + kStatusFile + ")"
                                   : "no increment converged; " + (failed / kStatusFile).string() +
                                         " records the failure";
  if (!details.empty())
    where += "; the whole residual history is in " + (failed / kFailureLog).string();
  if (fs::exists(run.target, ec))
    where += "; " + run.target.string() + " keeps the results of the last finished run";
  return where;
}

} // namespace bipot::app
