#pragma once
/// Internal to fem/linalg: MUMPS Schur complement of a distributed matrix, factorised by all
/// ranks together from their own rows (no rank holds the whole matrix).

#include "fem/linalg/detail/tpetra_types.hpp"

#include <Eigen/Dense>

#include <memory>
#include <string>
#include <vector>

namespace bipot::detail {

/// One MUMPS instance on MPI_COMM_WORLD with distributed assembled input (ICNTL(18) = 3):
/// each rank hands MUMPS the entries of the rows it owns, and MUMPS distributes the
/// factorisation over the ranks. The Schur complement (ICNTL(19) = 1) and the right-hand
/// sides of reduce()/expand() are centralised on rank 0 (vectors only) and broadcast or
/// scattered from there. Every call is collective; a MUMPS failure (INFOG(1) < 0, the same on
/// every rank) throws bipot::SolverError on every rank.
class DistributedSchur {
public:
  DistributedSchur();
  ~DistributedSchur();
  DistributedSchur(const DistributedSchur&) = delete;
  DistributedSchur& operator=(const DistributedSchur&) = delete;

  /// Factorises A with the global rows `schur_dofs` (sorted) as Schur variables I and writes
  /// S = A_II − A_IB A_BB⁻¹ A_BI into `S` on every rank (resized; MUMPS writes it there
  /// directly, so that no second copy of S coexists with MUMPS' workspace). `symmetric`: A is
  /// symmetric and is factorised LDLᵀ from its lower triangle (half the factors). The
  /// analysis is repeated only for another matrix object, another set of Schur variables or
  /// another symmetry.
  void factorize(const Teuchos::RCP<CrsMatrix>& A, const std::vector<long long>& schur_dofs,
                 bool symmetric, Eigen::MatrixXd& S);
  /// The factors of the next factorize() are written to files in `directory` (MUMPS
  /// out-of-core, ICNTL(22)) instead of kept in memory; empty: in memory (the default).
  /// A change takes effect with a new analysis.
  void set_factor_directory(const std::string& directory);
  /// b_I − A_IB A_BB⁻¹ b_B on every rank, for the owned block of b; keeps the partial
  /// solution (on rank 0) for the next expand().
  std::vector<double> reduce(const double* b_owned);
  /// x with x_I = `x_schur` (same on every rank) and x_B = A_BB⁻¹ (b_B − A_BI x_I), b that of
  /// the last reduce(); the owned block is written to `x_owned`.
  void expand(const std::vector<double>& x_schur, double* x_owned);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace bipot::detail
