#pragma once
/// Internal to fem/linalg: sparse direct solve of a distributed matrix on rank 0.

#include "fem/linalg/detail/tpetra_types.hpp"

#include <memory>
#include <string>
#include <vector>

namespace bipot::detail {

/// Gathers the whole matrix onto rank 0 and factorises it there on one process, with MUMPS
/// or Amesos2 KLU2 (root_factorization.hpp). Amesos2 13.2 as packaged here returns wrong
/// solutions when it gathers a matrix spread over several ranks itself (checked with a plain
/// Tpetra matrix: x came back equal to b), while its one-process path is correct; gathering
/// ourselves keeps to that path on any number of ranks. Memory on rank 0: the whole matrix
/// plus its factors, as with any serial direct solver.
class RootedDirectSolver {
public:
  /// `package`: "mumps" or "klu2" (validated by the LinearSolver options).
  explicit RootedDirectSolver(std::string package);
  ~RootedDirectSolver();

  /// Factorises A (collective). Called again for the same A after a refill, the structure
  /// gathered the first time and the symbolic analysis are reused.
  /// Throws bipot::SolverError on every rank if the factorisation fails.
  void factorize(const Teuchos::RCP<CrsMatrix>& A);

  /// x = A^{-1} b for the owned blocks of b and x (collective).
  void solve(const double* b_owned, double* x_owned);

  /// Factorises A keeping the global rows `schur_dofs` (sorted) as Schur variables I (MUMPS
  /// only, collective): afterwards take_schur() hands over S = A_II − A_IB A_BB⁻¹ A_BI on
  /// every rank (row-major; once per factorisation: no copy is kept). A new set of Schur variables
  /// repeats the analysis.
  /// `symmetric`: A is symmetric and is factorised LDLᵀ from its lower triangle.
  void factorize_with_schur(const Teuchos::RCP<CrsMatrix>& A,
                            const std::vector<long long>& schur_dofs, bool symmetric = false);
  std::vector<double> take_schur();
  /// b_I − A_IB A_BB⁻¹ b_B on every rank, for the owned block of b (collective). Keeps the
  /// partial solution for the next expand().
  std::vector<double> reduce(const double* b_owned);
  /// x with x_I = `x_schur` (same on every rank) and x_B = A_BB⁻¹ (b_B − A_BI x_I), b the
  /// vector of the last reduce(); owned block written to `x_owned` (collective).
  void expand(const std::vector<double>& x_schur, double* x_owned);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace bipot::detail
