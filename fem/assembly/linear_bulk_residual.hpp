#pragma once
/// The bulk residual of a linear (elastic) body from products with its stiffness instead of a
/// cell loop. SolidAssembler::assemble(u, c, nullptr, R) integrates every cell to give, with
/// the prescribed increments du_c of `c` eliminated,
///   R_free = −f_int(u + du_c),   R_c = diag(K)_c du_c,
/// and for a linear material f_int(v) = K_full v + f_int(0) (f_int(0) from an initial stress).
/// K, as factorised, has the constrained rows and columns eliminated; the entries the
/// elimination removed (rows or columns of constrained DOFs: the cells along the supports)
/// are kept in a second, small matrix C, so that
///   K_full v = K ṽ + C v,   ṽ = v with its constrained entries zeroed,
/// and R costs two sparse products. At 1M DOFs the cell loop took 22 s of a 145 s pile run.

#include "fem/assembly/constraints.hpp"
#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/sparse_matrix.hpp"

#include <memory>
#include <vector>

namespace bipot {

class SolidAssembler;

class LinearBulkResidual {
public:
  explicit LinearBulkResidual(const DofDistribution& dist) : f0_(dist) {}

  /// SolidAssembler::assemble(u, constraints, &K, R) (K zeroed and finished by the caller),
  /// keeping the removed entries and f_int(0) for residual(). Collective.
  void assemble(SolidAssembler& solid, const std::vector<double>& u, const Constraints& constraints,
                SparseMatrix& K, DistributedVector& R);
  /// Whether residual() may be used: after an assemble().
  bool ready() const { return removed_ != nullptr; }
  /// The initial stress changed (a displacement reset absorbed the stresses, a state was
  /// loaded): residual() integrates f_int(0) again first.
  void initial_stress_changed() { f0_stale_ = true; }
  /// What SolidAssembler::assemble(u, constraints, nullptr, R) adds to R (zeroed by the
  /// caller), from K and the kept entries: `constraints` must constrain the DOFs of the last
  /// assemble(), and K be the matrix it assembled. Collective.
  void residual(SolidAssembler& solid, const SparseMatrix& K, const std::vector<double>& u,
                const Constraints& constraints, DistributedVector& R);
  /// Adds the unconstrained internal force f_int(u) = K ũ + C u + f_int(0) (ũ = u with the
  /// constrained entries zeroed) to the owned rows of `f`, every row, as
  /// SolidAssembler::internal_force(u, f) does with a cell loop (the reactions after each
  /// increment: at 1M DOFs that loop was 0.3 s per increment). Only if `constraints` constrain
  /// the DOFs of the last assemble() (K its matrix): otherwise adds nothing and returns false.
  /// Collective.
  bool internal_force(SolidAssembler& solid, const SparseMatrix& K, const std::vector<double>& u,
                      const Constraints& constraints, DistributedVector& f);

private:
  /// Kv = K ṽ and Cv = C v for v = u + du_c (`with_increments`) or u, ṽ = v with the
  /// constrained entries du_c or 0 (f_int(0) refreshed first if stale).
  void products(SolidAssembler& solid, const SparseMatrix& K, const std::vector<double>& u,
                const Constraints& constraints, bool with_increments, DistributedVector& Kv,
                DistributedVector& Cv);
  void integrate_initial_force(SolidAssembler& solid, std::size_t num_dofs);
  std::unique_ptr<SparseMatrix> removed_;
  std::vector<Index> constrained_; ///< the DOFs the last assemble() eliminated, sorted
  DistributedVector f0_;
  bool f0_stale_ = true;
};

} // namespace bipot
