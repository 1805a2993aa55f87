#include "fem/linalg/communicator.hpp"

#include "fem/core/error.hpp"

#include <mpi.h>

#include <limits>

namespace bipot {

namespace {
// Collectives are valid only between MPI_Init and MPI_Finalize; outside that window the
// helpers act as a one-process run so that serial unit tests can use them.
bool mpi_active() {
  int initialized = 0;
  int finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  return initialized && !finalized;
}

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw Error(std::string("MPI call failed: ") + what);
}
} // namespace

int mpi_rank() {
  if (!mpi_active()) return 0;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int mpi_size() {
  if (!mpi_active()) return 1;
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

double sum_all(double local) {
  if (!mpi_active()) return local;
  double global = 0;
  check(MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD), "sum_all");
  return global;
}

Index sum_all(Index local) {
  if (!mpi_active()) return local;
  std::int64_t in = local;
  std::int64_t global = 0;
  check(MPI_Allreduce(&in, &global, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD), "sum_all");
  return global;
}

namespace {
void sum_in_place(void* values, Index count, MPI_Datatype type) {
  if (!mpi_active() || mpi_size() == 1 || count == 0) return;
  if (count > std::numeric_limits<int>::max()) throw Error("sum_all: too many values for MPI");
  check(MPI_Allreduce(MPI_IN_PLACE, values, static_cast<int>(count), type, MPI_SUM, MPI_COMM_WORLD),
        "sum_all (values)");
}
} // namespace

void sum_all(double* values, Index count) {
  sum_in_place(values, count, MPI_DOUBLE);
}

void sum_all(float* values, Index count) {
  sum_in_place(values, count, MPI_FLOAT);
}

double max_all(double local) {
  if (!mpi_active()) return local;
  double global = 0;
  check(MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "max_all");
  return global;
}

double min_all(double local) {
  if (!mpi_active()) return local;
  double global = 0;
  check(MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD), "min_all");
  return global;
}

void barrier() {
  if (mpi_active()) check(MPI_Barrier(MPI_COMM_WORLD), "barrier");
}

std::vector<double> gather_all(const std::vector<double>& local) {
  if (!mpi_active()) return local;
  const int size = mpi_size();
  const int count = static_cast<int>(local.size());
  std::vector<int> counts(size), displs(size);
  check(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD),
        "gather_all (counts)");
  int total = 0;
  for (int r = 0; r < size; ++r) {
    displs[r] = total;
    total += counts[r];
  }
  std::vector<double> global(total);
  check(MPI_Allgatherv(local.data(), count, MPI_DOUBLE, global.data(), counts.data(), displs.data(),
                       MPI_DOUBLE, MPI_COMM_WORLD),
        "gather_all");
  return global;
}

void broadcast(std::string& text, int root) {
  if (!mpi_active()) return;
  long length = static_cast<long>(text.size());
  check(MPI_Bcast(&length, 1, MPI_LONG, root, MPI_COMM_WORLD), "broadcast (length)");
  text.resize(static_cast<std::size_t>(length));
  if (length > 0)
    check(MPI_Bcast(text.data(), static_cast<int>(length), MPI_CHAR, root, MPI_COMM_WORLD),
          "broadcast");
}

} // namespace bipot
