#pragma once
/// Internal to fem/linalg: sparse LU factorisations of a matrix held whole by one process.

#include <cstddef>
#include <memory>
#include <string>
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
  /// The factorisation of the last factorize(): "LU", "LDL^T" (symmetric, with pivoting) or
  /// "Cholesky-type LDL^T" (positive definite, no pivoting).
  virtual const char* method() const = 0;
};

/// MUMPS multifrontal LU with the ordering MUMPS chooses (mumps_factorization.cpp); its
/// factors in files in `factor_directory` if not empty (out of core).
std::unique_ptr<RootFactorization> make_mumps_factorization(const std::string& factor_directory);
/// Amesos2 KLU2: left-looking LU with AMD ordering (klu2_factorization.cpp).
std::unique_ptr<RootFactorization> make_klu2_factorization();

} // namespace bipot::detail
