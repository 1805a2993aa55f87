// MUMPS on every rank for the Schur complement of generalized_newton: the bulk matrix is
// factorised from each rank's own rows, so memory and factorisation work are shared instead
// of the whole matrix being gathered on rank 0 (rooted_direct_solver.cpp).
#include "fem/linalg/detail/distributed_schur.hpp"

#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/detail/mumps_diagnosis.hpp"
#include "fem/linalg/detail/mumps_out_of_core.hpp"

#include <dmumps_c.h>
#include <mpi.h>

#include <algorithm>
#include <string>

namespace bipot::detail {

namespace {

std::vector<int> offsets(const std::vector<int>& counts) {
  std::vector<int> displs(counts.size(), 0);
  for (std::size_t i = 1; i < counts.size(); ++i)
    displs[i] = displs[i - 1] + counts[i - 1];
  return displs;
}

} // namespace

struct DistributedSchur::Impl {
  DMUMPS_STRUC_C id{};
  int rank = mpi_rank(), size = mpi_size();
  Teuchos::RCP<CrsMatrix> source; ///< the matrix whose structure was analysed
  std::vector<long long> schur_dofs;
  /// The entries MUMPS reads (1-based, as it counts), collected for the analysis and each
  /// factorisation and freed after it: the solves need only the factors, and at 1M DOFs these
  /// copies of K are 100s of MB.
  std::vector<MUMPS_INT> irn, jcn;
  std::vector<double> values;
  std::vector<MUMPS_INT> listvar;
  std::vector<double> rhs, redrhs;
  std::vector<int> owned_counts, owned_offsets; ///< rows per rank, for b and x
  bool initialised = false;
  bool symmetric = false;       ///< the instance factorises LDLᵀ (SYM = 2)
  std::string factor_directory; ///< out-of-core factors there (empty: in memory)

  // MUMPS fixes SYM when an instance is created (JOB = -1): another symmetry needs a new one.
  // General unsymmetric by default (friction makes a contact tangent unsymmetric); a
  // symmetric matrix (a linear elastic bulk) is factorised LDLᵀ, indefinite (SYM = 2):
  // constrained and rigid-body rows need not keep it positive definite.
  void create(bool sym) {
    destroy();
    id = DMUMPS_STRUC_C{};
    id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_WORLD));
    id.par = 1; // the host works too
    id.sym = sym ? 2 : 0;
    id.job = -1;
    dmumps_c(&id);
    initialised = id.infog[0] >= 0;
    if (!initialised)
      throw SolverError("direct solver (mumps, distributed): initialisation failed, INFOG(1) = " +
                        std::to_string(id.infog[0]));
    symmetric = sym;
    for (int k : {0, 1, 2})
      id.icntl[k] = -1; // no output: failures come back as INFOG codes
    id.icntl[3] = 0;
    id.icntl[6] = 7; // ICNTL(7): the ordering MUMPS chooses (when the analysis is centralised)
  }

  void destroy() {
    if (!initialised) return;
    id.job = -2; // collective, as the instance was created
    dmumps_c(&id);
    initialised = false;
  }

  // Every rank calls; INFOG(1) is global, so every rank throws or none does.
  void call(int job, const char* what) {
    id.job = job;
    dmumps_c(&id);
    const int code = id.infog[0];
    if (code >= 0) return;
    throw SolverError(std::string("direct solver (mumps, distributed) ") + what +
                      " failed: " + mumps_error(code, id.infog[1], id.icntl[21] != 0));
  }

  // This rank's entries of A in the same order every time (A's structure is fixed): a
  // symmetric matrix by its lower triangle, as MUMPS sums (i, j) and (j, i).
  void collect(const CrsMatrix& A) {
    const auto local = A.getLocalMatrixHost();
    const auto row_map = A.getRowMap();
    const auto col_map = A.getColMap();
    const std::size_t n_rows = A.getNodeNumRows();
    const std::size_t count =
        symmetric ? lower_count(A) : static_cast<std::size_t>(local.values.extent(0));
    irn.resize(count);
    jcn.resize(count);
    values.resize(count);
    std::size_t t = 0;
    for (std::size_t r = 0; r < n_rows; ++r) {
      const auto row = row_map->getGlobalElement(static_cast<Map::local_ordinal_type>(r));
      for (auto k = local.graph.row_map(r); k < local.graph.row_map(r + 1); ++k) {
        const auto col = col_map->getGlobalElement(local.graph.entries(k));
        if (symmetric && col > row) continue;
        irn[t] = static_cast<MUMPS_INT>(row + 1);
        jcn[t] = static_cast<MUMPS_INT>(col + 1);
        values[t++] = local.values(k);
      }
    }
    id.nnz_loc = static_cast<MUMPS_INT8>(count);
    id.irn_loc = irn.data();
    id.jcn_loc = jcn.data();
    id.a_loc = values.data();
  }
  std::size_t lower_count(const CrsMatrix& A) const {
    const auto local = A.getLocalMatrixHost();
    const auto row_map = A.getRowMap();
    const auto col_map = A.getColMap();
    std::size_t count = 0;
    for (std::size_t r = 0; r < A.getNodeNumRows(); ++r) {
      const auto row = row_map->getGlobalElement(static_cast<Map::local_ordinal_type>(r));
      for (auto k = local.graph.row_map(r); k < local.graph.row_map(r + 1); ++k)
        count += col_map->getGlobalElement(local.graph.entries(k)) <= row;
    }
    return count;
  }
  void release_entries() {
    std::vector<MUMPS_INT>().swap(irn);
    std::vector<MUMPS_INT>().swap(jcn);
    std::vector<double>().swap(values);
    id.irn_loc = id.jcn_loc = nullptr;
    id.a_loc = nullptr;
  }

  void analyse(const CrsMatrix& A) {
    collect(A);
    const int n_owned = static_cast<int>(A.getNodeNumRows());
    owned_counts.assign(size, 0);
    MPI_Allgather(&n_owned, 1, MPI_INT, owned_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    owned_offsets = offsets(owned_counts);
    const std::size_t n = A.getGlobalNumRows();
    id.n = static_cast<MUMPS_INT>(n);
    id.icntl[17] = 3; // ICNTL(18) = 3: distributed assembled matrix, entries given by each rank
    const std::size_t m = schur_dofs.size();
    listvar.resize(m);
    for (std::size_t i = 0; i < m; ++i)
      listvar[i] = static_cast<MUMPS_INT>(schur_dofs[i] + 1);
    redrhs.assign(m, 0.0);
    // ICNTL(19) = 1: the Schur complement centralised on the host (rank 0), by rows (its
    // lower triangle for a symmetric matrix); the list of its variables is read on the host.
    id.size_schur = static_cast<MUMPS_INT>(m);
    id.listvar_schur = listvar.data();
    id.schur_lld = static_cast<MUMPS_INT>(m);
    id.icntl[18] = m > 0 ? 1 : 0;
    // ICNTL(24) = 1: count null pivots (INFOG(28)); a singular A_BB is otherwise not reported.
    id.icntl[23] = m > 0 ? 1 : 0;
    call(1, "analysis");
  }
};

DistributedSchur::DistributedSchur() : impl_(std::make_unique<Impl>()) {
  impl_->create(false);
}

DistributedSchur::~DistributedSchur() {
  impl_->destroy();
}

void DistributedSchur::factorize(const Teuchos::RCP<CrsMatrix>& A,
                                 const std::vector<long long>& schur_dofs, bool symmetric,
                                 Eigen::MatrixXd& S) {
  auto& im = *impl_;
  if (im.source.get() != A.get() || im.schur_dofs != schur_dofs || im.symmetric != symmetric) {
    im.source = Teuchos::null; // not reusable if the analysis throws
    if (im.symmetric != symmetric) im.create(symmetric);
    set_mumps_out_of_core(im.id, im.factor_directory);
    im.schur_dofs = schur_dofs;
    im.analyse(*A);
    im.source = A;
  } else {
    im.collect(*A);
  }
  // The whole-mesh right-hand side of reduce()/expand() (n doubles on the host) is not needed
  // while MUMPS factorises, the run's peak out of core.
  std::vector<double>().swap(im.rhs);
  // S is written by the host during the factorisation, by rows; the solves after it do not
  // read it. The other ranks receive it afterwards, so their copy is not there at MUMPS' peak.
  const Eigen::Index m = static_cast<Eigen::Index>(schur_dofs.size());
  S.resize(im.rank == 0 ? m : 0, im.rank == 0 ? m : 0);
  im.id.schur = im.rank == 0 ? S.data() : nullptr;
  // Off-diagonal pivoting can need more workspace than the analysis estimated
  // (INFOG(1) = -8, -9): retry with a larger relaxation, as the MUMPS manual advises.
  for (int attempt = 0;; ++attempt) {
    im.id.job = 2;
    dmumps_c(&im.id);
    const int code = im.id.infog[0];
    if ((code == -8 || code == -9) && attempt < 4) {
      im.id.icntl[13] = std::max(40, 2 * im.id.icntl[13]); // ICNTL(14): % extra workspace
      continue;
    }
    if (code < 0) {
      im.call(2, "factorisation"); // throws with the diagnosis
    }
    break;
  }
  im.id.schur = nullptr;
  im.release_entries();
  if (!schur_dofs.empty() && im.id.infog[27] > 0)
    throw SolverError("direct solver (mumps, distributed) factorisation failed: numerically "
                      "singular matrix outside the Schur variables (" +
                      std::to_string(im.id.infog[27]) + " null pivots, MUMPS INFOG(28))");
  if (im.rank == 0) {
    // Column-major S holds MUMPS' rows as columns: Sᵀ.
    if (im.symmetric) {
      // MUMPS returns the lower triangle by rows (ICNTL(19) = 1, SYM = 2) and writes the other
      // triangle too, from workspace it did not initialise: mirror the lower one (the upper
      // triangle of Sᵀ).
      for (Eigen::Index j = 0; j < m; ++j)
        for (Eigen::Index i = j + 1; i < m; ++i)
          S(i, j) = S(j, i);
    } else {
      S.transposeInPlace();
    }
  } else {
    S.resize(m, m);
  }
  MPI_Bcast(S.data(), static_cast<int>(m * m), MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

void DistributedSchur::set_factor_directory(const std::string& directory) {
  auto& im = *impl_;
  if (directory == im.factor_directory) return;
  im.factor_directory = directory;
  im.source = Teuchos::null; // analysed for the other storage: analyse again
}

std::vector<double> DistributedSchur::reduce(const double* b_owned) {
  auto& im = *impl_;
  if (im.rank == 0) im.rhs.resize(static_cast<std::size_t>(im.id.n));
  MPI_Gatherv(b_owned, im.owned_counts[im.rank], MPI_DOUBLE, im.rhs.data(), im.owned_counts.data(),
              im.owned_offsets.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  im.id.rhs = im.rank == 0 ? im.rhs.data() : nullptr; // centralised on the host (ICNTL(20) = 0)
  im.id.redrhs = im.rank == 0 ? im.redrhs.data() : nullptr;
  im.id.lredrhs = im.id.size_schur;
  im.id.nrhs = 1;
  im.id.lrhs = im.id.n;
  im.id.icntl[25] = 1; // ICNTL(26) = 1: condensation (forward elimination) only
  try {
    im.call(3, "condensation");
  } catch (...) {
    im.id.icntl[25] = 0;
    throw;
  }
  im.id.icntl[25] = 0;
  std::vector<double> reduced(im.redrhs);
  MPI_Bcast(reduced.data(), static_cast<int>(reduced.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  return reduced;
}

void DistributedSchur::expand(const std::vector<double>& x_schur, double* x_owned) {
  auto& im = *impl_;
  if (im.rank == 0) std::copy(x_schur.begin(), x_schur.end(), im.redrhs.begin());
  im.id.rhs = im.rank == 0 ? im.rhs.data() : nullptr; // still the partial solution of reduce()
  im.id.redrhs = im.rank == 0 ? im.redrhs.data() : nullptr;
  im.id.icntl[25] = 2; // ICNTL(26) = 2: expansion from the Schur variables' solution
  try {
    im.call(3, "expansion");
  } catch (...) {
    im.id.icntl[25] = 0;
    throw;
  }
  im.id.icntl[25] = 0;
  MPI_Scatterv(im.rhs.data(), im.owned_counts.data(), im.owned_offsets.data(), MPI_DOUBLE, x_owned,
               im.owned_counts[im.rank], MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

} // namespace bipot::detail
