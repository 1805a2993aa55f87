#include "fem/linalg/parallel_environment.hpp"

#include "fem/linalg/communicator.hpp"

#include <Tpetra_Core.hpp>

namespace bipot {

struct ParallelEnvironment::Impl {
  Impl(int& argc, char**& argv) : guard(&argc, &argv) {}
  Tpetra::ScopeGuard guard;
};

ParallelEnvironment::ParallelEnvironment(int& argc, char**& argv)
    : impl_(std::make_unique<Impl>(argc, argv)), rank_(mpi_rank()), size_(mpi_size()) {}

ParallelEnvironment::~ParallelEnvironment() = default;

} // namespace bipot
