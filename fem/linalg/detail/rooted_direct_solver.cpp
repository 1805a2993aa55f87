#include "fem/linalg/detail/rooted_direct_solver.hpp"

#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"

#include <Amesos2.hpp>
#include <Teuchos_DefaultMpiComm.hpp>

#include <mpi.h>

#include <string>

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
template <class Work> void on_root(int rank, const char* stage, Work&& work) {
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
    throw SolverError(std::string("direct solver (KLU2) ") + stage + " failed: " + failure);
}

} // namespace

struct RootedDirectSolver::Impl {
  using Solver = Amesos2::Solver<CrsMatrix, MultiVector>;
  int rank = mpi_rank();
  int size = mpi_size();
  Teuchos::RCP<CrsMatrix> source; ///< the distributed matrix whose structure we hold
  std::vector<int> owned_counts;  ///< owned rows per rank (rank 0), for b and x
  // Rank 0 only: the gathered matrix on a one-process communicator.
  std::vector<GO> row_cols;         ///< column of each gathered entry, rows in global order
  std::vector<std::size_t> row_ptr; ///< gathered CSR offsets
  Teuchos::RCP<CrsMatrix> root_matrix;
  Teuchos::RCP<MultiVector> root_x, root_b;
  Teuchos::RCP<Solver> solver;

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
  row_cols = gather_to_root(cols, MPI_INT64_T, rank, size);
  on_root(rank, "setup", [&] {
    const GO n = static_cast<GO>(all_sizes.size());
    row_ptr.assign(all_sizes.size() + 1, 0);
    for (std::size_t r = 0; r < all_sizes.size(); ++r)
      row_ptr[r + 1] = row_ptr[r] + all_sizes[r];
    auto self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
    auto map = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(n), GO(0), self));
    std::vector<std::size_t> counts(all_sizes.begin(), all_sizes.end());
    auto graph = Teuchos::rcp(
        new CrsGraph(map, Teuchos::ArrayView<const std::size_t>(counts.data(), counts.size()),
                     Tpetra::StaticProfile));
    for (GO r = 0; r < n; ++r)
      graph->insertGlobalIndices(r, static_cast<int>(all_sizes[r]), row_cols.data() + row_ptr[r]);
    graph->fillComplete();
    root_matrix = Teuchos::rcp(new CrsMatrix(graph));
    root_x = Teuchos::rcp(new MultiVector(map, 1));
    root_b = Teuchos::rcp(new MultiVector(map, 1));
  });
}

std::vector<double> RootedDirectSolver::Impl::gather_values(const CrsMatrix& A) const {
  const auto local = A.getLocalMatrixHost();
  std::vector<double> values(local.values.data(), local.values.data() + local.values.extent(0));
  return gather_to_root(values, MPI_DOUBLE, rank, size);
}

RootedDirectSolver::RootedDirectSolver() : impl_(std::make_unique<Impl>()) {}
RootedDirectSolver::~RootedDirectSolver() = default;

void RootedDirectSolver::factorize(const Teuchos::RCP<CrsMatrix>& A) {
  auto& im = *impl_;
  const bool same_structure = im.source.get() == A.get();
  if (!same_structure) {
    im.solver = Teuchos::null;
    im.gather_structure(*A);
    im.source = A;
  }
  const auto values = im.gather_values(*A);
  on_root(im.rank, "factorisation", [&] {
    auto& M = *im.root_matrix;
    if (M.isFillComplete()) M.resumeFill();
    const GO n = static_cast<GO>(im.row_ptr.size()) - 1;
    for (GO r = 0; r < n; ++r) {
      const auto begin = im.row_ptr[r];
      const int count = static_cast<int>(im.row_ptr[r + 1] - begin);
      M.replaceGlobalValues(r, count, values.data() + begin, im.row_cols.data() + begin);
    }
    M.fillComplete();
    if (im.solver.is_null()) {
      im.solver = Amesos2::create<CrsMatrix, MultiVector>("KLU2", im.root_matrix);
      im.solver->symbolicFactorization();
    }
    im.solver->numericFactorization();
  });
}

void RootedDirectSolver::solve(const double* b_owned, double* x_owned) {
  auto& im = *impl_;
  const int n_owned = static_cast<int>(im.source->getNodeNumRows());
  const auto displs = displacements(im.owned_counts);
  std::vector<double> b_all, x_all;
  if (im.rank == 0) {
    b_all.resize(im.root_b->getLocalLength());
    x_all.resize(b_all.size());
  }
  MPI_Gatherv(b_owned, n_owned, MPI_DOUBLE, b_all.data(), im.owned_counts.data(), displs.data(),
              MPI_DOUBLE, 0, MPI_COMM_WORLD);
  on_root(im.rank, "solve", [&] {
    { // host views released before Amesos2 touches the vectors
      auto b = im.root_b->getDataNonConst(0);
      std::copy(b_all.begin(), b_all.end(), b.getRawPtr());
    }
    im.solver->solve(im.root_x.ptr(), im.root_b.ptr());
    auto x = im.root_x->getData(0);
    std::copy(x.getRawPtr(), x.getRawPtr() + x_all.size(), x_all.begin());
  });
  MPI_Scatterv(x_all.data(), im.owned_counts.data(), displs.data(), MPI_DOUBLE, x_owned, n_owned,
               MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

} // namespace bipot::detail
