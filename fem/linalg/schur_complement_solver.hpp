#pragma once
/// Static condensation of a SparseMatrix onto a few of its DOFs (MUMPS Schur complement).

#include "fem/core/types.hpp"

#include <memory>
#include <string>
#include <vector>

namespace bipot {

class DistributedVector;
class SparseMatrix;

/// Splits the DOFs of A into a small set I (e.g. the interface DOFs) and the rest B, and
/// factorises A_BB once while MUMPS forms the dense Schur complement
///     S = A_II − A_IB A_BB⁻¹ A_BI            (ICNTL(19)).
/// A system A x = b with an extra nonlinearity on I only, A x = b − f(x_I), then reduces
/// exactly to |I| equations S x_I = c − f(x_I) with c = b_I − A_IB A_BB⁻¹ b_B (reduce()),
/// and x_B follows from x_I by one back substitution (expand()). While A does not change,
/// nonlinear iterations on I cost nothing that grows with the rest of the mesh.
///
/// Every rank hands MUMPS its own rows and the factorisation is shared by all ranks (no rank
/// holds the whole matrix); S and c are broadcast, so every rank can run the same dense
/// iteration on I.
class SchurComplementSolver {
public:
  SchurComplementSolver();
  ~SchurComplementSolver();
  SchurComplementSolver(const SchurComplementSolver&) = delete;
  SchurComplementSolver& operator=(const SchurComplementSolver&) = delete;

  /// Factorises A with `schur_dofs` (global DOFs, any order, no duplicates) as I
  /// (collective). Throws bipot::SolverError on every rank if the factorisation fails
  /// (A_BB singular: some part of the model is held only through I).
  /// `symmetric`: A is symmetric (a linear elastic bulk); MUMPS then factorises LDLᵀ from
  /// its lower triangle, with half the factors (memory, factorisation, reduce and expand).
  void factorize(const SparseMatrix& A, const std::vector<Index>& schur_dofs,
                 bool symmetric = false);

  /// The factors of A_BB written to files in `directory` (MUMPS out of core) from the next
  /// factorize() on, instead of kept in memory: for models whose factors do not fit. Empty:
  /// in memory (the default). The files go when the solver does.
  void set_factor_directory(const std::string& directory);

  /// The DOFs of I in the order of schur() rows and columns (sorted).
  const std::vector<Index>& schur_dofs() const { return dofs_; }
  /// S (|I| × |I|), identical on every rank.
  const Eigen::MatrixXd& schur() const { return schur_; }

  /// c = b_I − A_IB A_BB⁻¹ b_B on every rank (collective). Remembers b for expand().
  Eigen::VectorXd reduce(const DistributedVector& b);
  /// x with x_I = `x_schur` and x_B = A_BB⁻¹ (b_B − A_BI x_I), b that of the last reduce()
  /// (collective; `x_schur` must be the same on every rank).
  void expand(const Eigen::VectorXd& x_schur, DistributedVector& x);

  /// max |S_ij − S_ji| / max |S_ij|: round-off (~1e-15) when A is symmetric, as a linear
  /// elastic bulk is; then S x can read one triangle only (half the bytes).
  double asymmetry() const { return asymmetry_; }
  /// S is symmetric to round-off.
  bool symmetric() const { return asymmetry_ <= symmetric_within; }
  static constexpr double symmetric_within = 1e-12;

  /// Seconds in the last factorize() (analysis included when it ran).
  double setup_seconds() const { return setup_seconds_; }

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<Index> dofs_;
  Eigen::MatrixXd schur_;
  double setup_seconds_ = 0;
  double asymmetry_ = 0;
};

} // namespace bipot
