#pragma once
/// MPI + Kokkos lifetime for a program that uses fem/linalg.

#include <memory>

namespace bipot {

/// Create exactly one, first thing in main(), and keep it alive until the end: initialises
/// MPI (unless already initialised) and Kokkos through Tpetra, and finalises what it
/// initialised when destroyed. Every distributed object must be destroyed before it.
class ParallelEnvironment {
public:
  /// May remove MPI/Kokkos options from argc/argv.
  ParallelEnvironment(int& argc, char**& argv);
  ~ParallelEnvironment();
  ParallelEnvironment(const ParallelEnvironment&) = delete;
  ParallelEnvironment& operator=(const ParallelEnvironment&) = delete;

  /// Rank of this process in MPI_COMM_WORLD.
  int rank() const { return rank_; }
  /// Number of processes in MPI_COMM_WORLD.
  int size() const { return size_; }

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int rank_ = 0;
  int size_ = 1;
};

} // namespace bipot
