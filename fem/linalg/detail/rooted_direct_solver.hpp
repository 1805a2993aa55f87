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
  /// `factor_directory`: MUMPS writes its factors there (out of core); empty: in memory.
  explicit RootedDirectSolver(std::string package, std::string factor_directory = "");
  ~RootedDirectSolver();

  /// Factorises A (collective). Called again for the same A after a refill, the structure
  /// gathered the first time and the symbolic analysis are reused.
  /// Throws bipot::SolverError on every rank if the factorisation fails.
  void factorize(const Teuchos::RCP<CrsMatrix>& A);

  /// x = A^{-1} b for the owned blocks of b and x (collective).
  void solve(const double* b_owned, double* x_owned);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace bipot::detail
