#pragma once
/// Internal to fem/linalg: the sparse LU of an earlier matrix as a GMRES preconditioner.

#include "fem/linalg/detail/rooted_direct_solver.hpp"
#include "fem/linalg/detail/tpetra_types.hpp"

namespace bipot::detail {

/// Applies A_old⁻¹ (the LU factors of the matrix given to the last factorize()) as a Tpetra
/// Operator. Contact Newton iterations change only the interface rows of the tangent, so A
/// differs from A_old by a low-rank term and right-preconditioned GMRES converges in about
/// as many iterations as that rank, instead of a new factorisation per iteration (whose cost
/// grows like N^1.5 on our 2D meshes). The caller decides when to refactorise.
class LuPreconditioner : public Operator {
public:
  /// `package`: the sparse LU to use, "mumps" or "klu2".
  LuPreconditioner(const std::string& package, const std::string& factor_directory)
      : lu_(package, factor_directory) {}

  /// Factorises A (collective) and takes its row map as domain and range.
  void factorize(const Teuchos::RCP<CrsMatrix>& A);
  bool factorized() const { return !map_.is_null(); }

  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  /// Y = alpha A_old⁻¹ X + beta Y, column by column (collective). NO_TRANS only.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             double alpha = 1.0, double beta = 0.0) const override;

private:
  mutable RootedDirectSolver lu_; // solve() is logically const: the factors do not change
  Teuchos::RCP<const Map> map_;
};

} // namespace bipot::detail
