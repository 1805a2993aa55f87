#include "apps/common/app_support.hpp"
#include "apps/common/run_folder.hpp"

#include "fem/linalg/communicator.hpp"

#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

namespace bipot::app {

namespace {

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

void prepare_error_handling() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (error_comm != MPI_COMM_NULL || !initialized || finalized || mpi_size() == 1) return;
  MPI_Comm_dup(MPI_COMM_WORLD, &error_comm);
}

int report_error(const std::exception& e, int code, const std::string& program) {
  if (!every_rank_failed(kErrorAgreementSeconds)) {
    const std::string where = fail_open_run_folder(e.what());
    std::cerr << error_text(e, program + ": rank " + std::to_string(mpi_rank()) + " of " +
                                   std::to_string(mpi_size()) + ": ");
    if (!where.empty()) std::cerr << program << ": " << where << "\n";
    std::cerr.flush();
    std::fflush(stdout);
    MPI_Abort(MPI_COMM_WORLD, code);
  }
  if (mpi_rank() != 0) return code;
  const std::string where = fail_open_run_folder(e.what());
  std::cerr << error_text(e, program + ": ");
  if (!where.empty()) std::cerr << program << ": " << where << "\n";
  return code;
}

double peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}

} // namespace bipot::app
