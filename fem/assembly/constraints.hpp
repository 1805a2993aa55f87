#pragma once
/// Prescribed values on DOFs (Dirichlet conditions), replicated on every rank, applied by
/// symmetric elimination on each local (element) system before it is added to the global
/// one — as deal.II's distribute_local_to_global does. The global matrix stays symmetric
/// positive definite (CG + MueLu apply) and no global row/column surgery across ranks is
/// needed.

#include "fem/core/types.hpp"

#include <unordered_map>

namespace bipot {

class Constraints {
public:
  void clear() { values_.clear(); }
  /// Prescribes the increment `value` for `dof` in the next solve (0 keeps it fixed).
  void set(Index dof, double value) { values_[dof] = value; }
  bool is_constrained(Index dof) const { return values_.count(dof) != 0; }
  double value(Index dof) const;
  const std::unordered_map<Index, double>& values() const { return values_; }

  /// Eliminates the constrained DOFs from a local system K du = R (K row-major n×n):
  /// R_b −= K_bc du_c for free b; rows and columns of c zeroed, K_cc kept (its positive
  /// diagonal) and R_c = K_cc du_c, so that the sum over cells forces du_c exactly.
  void condense(const Index* dofs, int n, double* K, double* R) const;
  /// Zeroes the constrained entries of a local right-hand side (loads: a constrained DOF's
  /// equation is owned by the elimination above).
  void condense(const Index* dofs, int n, double* R) const;

private:
  std::unordered_map<Index, double> values_;
};

} // namespace bipot
