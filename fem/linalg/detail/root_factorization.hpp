#pragma once
/// Internal to fem/linalg: sparse LU factorisations of a matrix held whole by one process.

#include <cstddef>
#include <memory>
#include <vector>

namespace bipot::detail {

/// A square sparse matrix in CSR form with 0-based global columns, as RootedDirectSolver
/// gathers it on rank 0. The structure stays fixed between analyse() calls.
struct RootCsr {
  std::vector<std::size_t> row_ptr; ///< n + 1 offsets
  std::vector<long long> cols;      ///< column of each entry, rows in order (Tpetra GO)
  std::size_t size() const { return row_ptr.empty() ? 0 : row_ptr.size() - 1; }
};

/// One sparse LU package, called on one process only. Failures throw std::runtime_error
/// with the package's own diagnosis (singular matrix, memory); the caller adds the context.
class RootFactorization {
public:
  virtual ~RootFactorization() = default;
  /// Ordering and symbolic factorisation for this structure (kept by reference: it must
  /// outlive the factorisation).
  virtual void analyse(const RootCsr& structure) = 0;
  /// Numerical factorisation; `values` in the order of the analysed structure's entries.
  virtual void factorize(const std::vector<double>& values) = 0;
  /// x = A⁻¹ b for vectors of length n.
  virtual void solve(const double* b, double* x) = 0;

  // Schur complement on a set of variables I (the rest B): S = A_II − A_IB A_BB⁻¹ A_BI.
  // Only MUMPS offers it (ICNTL(19)); the defaults throw.

  /// Keeps `variables` (0-based, sorted) as Schur variables: call before analyse(). After
  /// each factorize(), take_schur() hands over S (row-major, size |I|²; no copy is kept).
  virtual void set_schur_variables(const std::vector<long long>& variables);
  virtual std::vector<double> take_schur();
  /// Condensation of b (length n): `reduced` (length |I|) = b_I − A_IB A_BB⁻¹ b_B. `work`
  /// (length n) receives the package's partial solution and must be passed unchanged to
  /// expand().
  virtual void reduce(const double* b, double* work, double* reduced);
  /// Expansion: x (length n) with x_I = `x_schur` and x_B = A_BB⁻¹ (b_B − A_BI x_I), b the
  /// vector of the reduce() that filled `work`.
  virtual void expand(double* work, const double* x_schur, double* x);
};

/// MUMPS multifrontal LU with the ordering MUMPS chooses (mumps_factorization.cpp).
/// `symmetric`: the matrices are symmetric; MUMPS then factorises LDLᵀ from their lower
/// triangle (half the factors' memory and time).
std::unique_ptr<RootFactorization> make_mumps_factorization(bool symmetric = false);
/// Amesos2 KLU2: left-looking LU with AMD ordering (klu2_factorization.cpp).
std::unique_ptr<RootFactorization> make_klu2_factorization();

} // namespace bipot::detail
