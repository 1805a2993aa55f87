#include "fem/assembly/linear_bulk_residual.hpp"

#include "fem/assembly/solid_assembler.hpp"
#include "fem/linalg/sparsity_pattern.hpp"

namespace bipot {

void LinearBulkResidual::assemble(SolidAssembler& solid, const std::vector<double>& u,
                                  const Constraints& constraints, SparseMatrix& K,
                                  DistributedVector& R) {
  const DofDistribution& dist = R.distribution();
  SparsityPattern pattern;
  solid.add_to_pattern(pattern, &constraints);
  removed_ = std::make_unique<SparseMatrix>(dist, pattern);
  removed_->set_zero();
  solid.assemble(u, constraints, &K, R, removed_.get());
  removed_->finish_assembly();
  integrate_initial_force(solid, u.size());
}

void LinearBulkResidual::integrate_initial_force(SolidAssembler& solid, std::size_t num_dofs) {
  f0_.set_zero();
  if (solid.has_initial_stress()) solid.internal_force(std::vector<double>(num_dofs, 0.0), f0_);
  f0_.finish_assembly();
  f0_stale_ = false;
}

void LinearBulkResidual::residual(SolidAssembler& solid, const SparseMatrix& K,
                                  const std::vector<double>& u, const Constraints& constraints,
                                  DistributedVector& R) {
  if (f0_stale_) integrate_initial_force(solid, u.size());
  const DofDistribution& dist = R.distribution();
  const Index first = dist.first_owned_dof(), n = dist.num_owned_dofs();
  // v = u + du_c; ṽ = v with the constrained entries replaced by du_c, so that K ṽ gives
  // K_ff u_f on the free rows and diag(K)_c du_c on the constrained ones.
  DistributedVector v(dist), v_free(dist), Kv(dist), Cv(dist);
  double* vv = v.owned_values();
  double* vf = v_free.owned_values();
  for (Index i = 0; i < n; ++i) {
    const Index d = first + i;
    const bool c = constraints.is_constrained(d);
    const double du = c ? constraints.value(d) : 0.0;
    vv[i] = u[d] + du;
    vf[i] = c ? du : u[d];
  }
  K.multiply(v_free, Kv);
  removed_->multiply(v, Cv);
  double* r = R.owned_values();
  const double* kv = Kv.owned_values();
  const double* cv = Cv.owned_values();
  const double* f0 = f0_.owned_values();
  for (Index i = 0; i < n; ++i)
    r[i] += constraints.is_constrained(first + i) ? kv[i] : -(kv[i] + cv[i] + f0[i]);
}

} // namespace bipot
