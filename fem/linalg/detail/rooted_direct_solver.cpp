#include "fem/linalg/detail/rooted_direct_solver.hpp"

#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/detail/root_factorization.hpp"

#include <mpi.h>

#include <string>
#include <utility>

namespace bipot::detail {

namespace {

std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> displs(counts.size(), 0);
  for (std::size_t i = 1; i < counts.size(); ++i)
    displs[i] = displs[i - 1] + counts[i - 1];
  return displs;
}

// Gathers per-rank arrays of different lengths onto rank 0 (in rank order).
template <class T>
std::vector<T> gather_to_root(const std::vector<T>& local, MPI_Datatype type, int rank, int size) {
  const int count = static_cast<int>(local.size());
  std::vector<int> counts(size, 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  const auto displs = displacements(counts);
  std::vector<T> all(rank == 0 ? static_cast<std::size_t>(displs.back() + counts.back()) : 0);
  MPI_Gatherv(local.data(), count, type, all.data(), counts.data(), displs.data(), type, 0,
              MPI_COMM_WORLD);
  return all;
}

// Runs `work` on rank 0 and makes its failure, if any, a SolverError on every rank, so that
// no rank is left waiting in a collective.
template <class Work>
void on_root(int rank, const std::string& package, const char* stage, Work&& work) {
  std::string failure;
  if (rank == 0) {
    try {
      work();
    } catch (const std::exception& e) {
      failure = e.what();
      if (failure.empty()) failure = "unknown error";
    }
  }
  broadcast(failure, 0);
  if (!failure.empty())
    throw SolverError("direct solver (" + package + ") " + stage + " failed: " + failure);
}

} // namespace

struct RootedDirectSolver::Impl {
  std::string package;
  std::string factor_directory;
  int rank = mpi_rank();
  int size = mpi_size();
  Teuchos::RCP<CrsMatrix> source; ///< the distributed matrix whose structure we hold
  std::vector<int> owned_counts;  ///< owned rows per rank (rank 0), for b and x
  // Rank 0 only: the gathered structure and its factorisation.
  RootCsr structure;
  std::unique_ptr<RootFactorization> lu;

  void gather_structure(const CrsMatrix& A);
  std::vector<double> gather_values(const CrsMatrix& A) const;
};

void RootedDirectSolver::Impl::gather_structure(const CrsMatrix& A) {
  const auto local = A.getLocalMatrixHost();
  const auto col_map = A.getColMap();
  const std::size_t n_rows = A.getNodeNumRows();
  std::vector<GO> sizes(n_rows), cols(local.graph.entries.extent(0));
  for (std::size_t r = 0; r < n_rows; ++r)
    sizes[r] = static_cast<GO>(local.graph.row_map(r + 1) - local.graph.row_map(r));
  for (std::size_t k = 0; k < cols.size(); ++k)
    cols[k] = col_map->getGlobalElement(local.graph.entries(k));
  const int n_owned = static_cast<int>(n_rows);
  owned_counts.assign(size, 0);
  MPI_Gather(&n_owned, 1, MPI_INT, owned_counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  const auto all_sizes = gather_to_root(sizes, MPI_INT64_T, rank, size);
  auto all_cols = gather_to_root(cols, MPI_INT64_T, rank, size);
  on_root(rank, package, "analysis", [&] {
    structure.cols = std::move(all_cols); // the gathered copy can be 100s of MB at 1M DOFs
    structure.row_ptr.assign(all_sizes.size() + 1, 0);
    for (std::size_t r = 0; r < all_sizes.size(); ++r)
      structure.row_ptr[r + 1] = structure.row_ptr[r] + static_cast<std::size_t>(all_sizes[r]);
    lu = package == "klu2" ? make_klu2_factorization() : make_mumps_factorization(factor_directory);
    lu->analyse(structure);
    // MUMPS copied the indices it needs: the gathered columns (8 bytes per entry) can go.
    // KLU2 keeps reading them at every factorisation.
    if (package != "klu2") std::vector<long long>().swap(structure.cols);
  });
}

std::vector<double> RootedDirectSolver::Impl::gather_values(const CrsMatrix& A) const {
  const auto local = A.getLocalMatrixHost();
  std::vector<double> values(local.values.data(), local.values.data() + local.values.extent(0));
  return gather_to_root(values, MPI_DOUBLE, rank, size);
}

RootedDirectSolver::RootedDirectSolver(std::string package, std::string factor_directory)
    : impl_(std::make_unique<Impl>()) {
  impl_->package = std::move(package);
  impl_->factor_directory = std::move(factor_directory);
}
RootedDirectSolver::~RootedDirectSolver() = default;

void RootedDirectSolver::factorize(const Teuchos::RCP<CrsMatrix>& A) {
  auto& im = *impl_;
  if (im.source.get() != A.get()) {
    im.source = Teuchos::null; // not reusable if the analysis throws
    im.gather_structure(*A);
    im.source = A;
  }
  const auto values = im.gather_values(*A);
  on_root(im.rank, im.package, "factorisation", [&] { im.lu->factorize(values); });
}

void RootedDirectSolver::solve(const double* b_owned, double* x_owned) {
  auto& im = *impl_;
  const int n_owned = static_cast<int>(im.source->getNodeNumRows());
  const auto displs = displacements(im.owned_counts);
  std::vector<double> b_all, x_all;
  if (im.rank == 0) {
    b_all.resize(im.structure.size());
    x_all.resize(b_all.size());
  }
  MPI_Gatherv(b_owned, n_owned, MPI_DOUBLE, b_all.data(), im.owned_counts.data(), displs.data(),
              MPI_DOUBLE, 0, MPI_COMM_WORLD);
  on_root(im.rank, im.package, "solve", [&] { im.lu->solve(b_all.data(), x_all.data()); });
  MPI_Scatterv(x_all.data(), im.owned_counts.data(), displs.data(), MPI_DOUBLE, x_owned, n_owned,
               MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

} // namespace bipot::detail
