#include "apps/common/app_support.hpp"
#include "apps/common/run_folder.hpp"

#include "fem/linalg/communicator.hpp"
#include "fem/linalg/parallel_environment.hpp"

#include <mpi.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>
#ifdef __GLIBC__
#include <malloc.h> // mallopt
#endif

namespace bipot::app {

namespace {

// The Kokkos 3.4 options an app passes on: without a value, and with an integer value
// (num-devices: "N" or "N,M"); the tools options take any text.
const std::vector<std::string> kokkos_flags = {"--kokkos-help", "--kokkos-disable-warnings",
                                               "--kokkos-tune-internals"};
const std::vector<std::string> kokkos_integers = {"--kokkos-threads", "--kokkos-numa",
                                                  "--kokkos-device-id", "--kokkos-num-devices"};
const std::vector<std::string> kokkos_texts = {"--kokkos-tools-library", "--kokkos-tools-args"};

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// A count Kokkos reads with std::stoi: digits only, at most 9 of them (no overflow).
bool is_count(const std::string& s) {
  return !s.empty() && s.size() <= 9 &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

// "" if Kokkos can take `arg`, else why not.
std::string kokkos_option_problem(const std::string& arg) {
  const auto eq = arg.find('=');
  const std::string name = arg.substr(0, eq);
  const std::string value = eq == std::string::npos ? "" : arg.substr(eq + 1);
  if (contains(kokkos_flags, name)) return eq == std::string::npos ? "" : "takes no value";
  if (contains(kokkos_texts, name)) return eq == std::string::npos ? "expects =TEXT" : "";
  if (!contains(kokkos_integers, name)) {
    std::string known;
    for (const auto* list : {&kokkos_flags, &kokkos_integers, &kokkos_texts})
      for (const auto& k : *list)
        known += (known.empty() ? "" : ", ") + k;
    return "unknown Kokkos option; known: " + known;
  }
  const auto comma = value.find(',');
  const bool ok = name == "--kokkos-num-devices" && comma != std::string::npos
                      ? is_count(value.substr(0, comma)) && is_count(value.substr(comma + 1))
                      : is_count(value);
  return ok ? "" : "expects =N, a whole number from 0 to 999999999";
}

// Errors before MPI starts: print once per job, from the launcher's rank 0.
bool launcher_rank_zero() {
  for (const char* var : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
    if (const char* rank = std::getenv(var)) return std::string(rank) == "0";
  return true;
}

// A duplicate of MPI_COMM_WORLD, so that the error handling's barrier cannot match a
// collective call of the solver on the ranks that did not fail.
MPI_Comm error_comm = MPI_COMM_NULL;

// True when every rank reaches this call within `seconds`: the error is collective.
bool every_rank_failed(double seconds) {
  if (error_comm == MPI_COMM_NULL) return true;
  MPI_Request request;
  MPI_Ibarrier(error_comm, &request);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int done = 0;
  while (true) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done || std::chrono::steady_clock::now() > deadline) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return done != 0;
}

std::string error_text(const std::exception& e, const std::string& prefix) {
  std::ostringstream out;
  if (auto input = dynamic_cast<const InputError*>(&e)) {
    const auto n = input->problems().size();
    out << prefix << "invalid input (" << n << " problem" << (n == 1 ? "" : "s") << "):\n";
    for (const auto& p : input->problems())
      out << "  " << p << "\n";
  } else {
    out << prefix << e.what() << "\n";
  }
  return out.str();
}

} // namespace

std::unique_ptr<ParallelEnvironment>
start_parallel(int argc, char** argv, const std::string& program, std::vector<std::string>& args) {
  // Kokkos may keep pointers into its argv: storage for the whole run.
  static std::vector<std::string> kokkos_args;
  static std::vector<char*> kokkos_argv;
  kokkos_args = {argc > 0 ? argv[0] : program};
  args.clear();
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--kokkos-", 0) != 0) {
      args.push_back(arg);
      continue;
    }
    const std::string problem = kokkos_option_problem(arg);
    if (!problem.empty()) {
      if (launcher_rank_zero()) std::cerr << program << ": " << arg << ": " << problem << "\n";
      return nullptr;
    }
    kokkos_args.push_back(arg);
  }
  kokkos_argv.clear();
  for (auto& a : kokkos_args)
    kokkos_argv.push_back(a.data());
  kokkos_argv.push_back(nullptr);
#ifdef __GLIBC__
  // Arrays of 1 MiB and more are mapped and go back to the system when freed. glibc raises
  // that threshold, by default, to the size of each large array freed (up to 32 MiB), after
  // which freed whole-mesh arrays stay in the heap: the pile at 936k DOFs out of core peaked
  // at 1038 MiB instead of 938 (docs/performance_solver_engine.md).
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
  int kokkos_argc = static_cast<int>(kokkos_args.size());
  char** kokkos_argv_ptr = kokkos_argv.data();
  try {
    return std::make_unique<ParallelEnvironment>(kokkos_argc, kokkos_argv_ptr);
  } catch (const std::exception& e) {
    if (launcher_rank_zero())
      std::cerr << program << ": cannot start MPI and Kokkos: " << e.what() << "\n";
    return nullptr;
  }
}

void prepare_error_handling() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (error_comm != MPI_COMM_NULL || !initialized || finalized || mpi_size() == 1) return;
  MPI_Comm_dup(MPI_COMM_WORLD, &error_comm);
}

namespace {
// What an error carries beyond its message (the residual history of a failed increment).
std::string details_of(const std::exception& e) {
  const auto* failure = dynamic_cast<const IncrementFailure*>(&e);
  return failure ? failure->details() : std::string();
}
} // namespace

int report_error(const std::exception& e, int code, const std::string& program) {
  if (!every_rank_failed(kErrorAgreementSeconds)) {
    const std::string where = fail_open_run_folder(e.what(), details_of(e));
    std::cerr << error_text(e, program + ": rank " + std::to_string(mpi_rank()) + " of " +
                                   std::to_string(mpi_size()) + ": ");
    if (!where.empty()) std::cerr << program << ": " << where << "\n";
    std::cerr.flush();
    std::fflush(stdout);
    MPI_Abort(MPI_COMM_WORLD, code);
  }
  if (mpi_rank() != 0) return code;
  const std::string where = fail_open_run_folder(e.what(), details_of(e));
  std::cerr << error_text(e, program + ": ");
  if (!where.empty()) std::cerr << program << ": " << where << "\n";
  return code;
}

double peak_memory_mib() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}

} // namespace bipot::app
