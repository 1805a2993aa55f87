#include "fem/assembly/linear_bulk_residual.hpp"

#include "fem/assembly/solid_assembler.hpp"
#include "fem/linalg/sparsity_pattern.hpp"

#include <algorithm>

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
  constrained_.clear();
  for (const auto& kv : constraints.values())
    constrained_.push_back(kv.first);
  std::sort(constrained_.begin(), constrained_.end());
  integrate_initial_force(solid, u.size());
}

void LinearBulkResidual::integrate_initial_force(SolidAssembler& solid, std::size_t num_dofs) {
  f0_.set_zero();
  if (solid.has_initial_stress()) solid.internal_force(std::vector<double>(num_dofs, 0.0), f0_);
  f0_.finish_assembly();
  f0_stale_ = false;
}

void LinearBulkResidual::products(SolidAssembler& solid, const SparseMatrix& K,
                                  const std::vector<double>& u, const Constraints& constraints,
                                  bool with_increments, DistributedVector& Kv,
                                  DistributedVector& Cv) {
  if (f0_stale_) integrate_initial_force(solid, u.size());
  const DofDistribution& dist = Kv.distribution();
  const Index first = dist.first_owned_dof(), n = dist.num_owned_dofs();
  // v = u + du_c; ṽ = v with the constrained entries replaced by du_c (0 without increments):
  // K's constrained rows hold only their diagonal, so K ṽ gives K_ff u_f on the free rows and
  // diag(K)_c du_c on the constrained ones; C holds the rest of the constrained rows and the
  // constrained columns of the free ones.
  DistributedVector v(dist), v_free(dist);
  double* vv = v.owned_values();
  double* vf = v_free.owned_values();
  for (Index i = 0; i < n; ++i) {
    const Index d = first + i;
    const bool c = constraints.is_constrained(d);
    const double du = c && with_increments ? constraints.value(d) : 0.0;
    vv[i] = u[d] + du;
    vf[i] = c ? du : u[d];
  }
  K.multiply(v_free, Kv);
  removed_->multiply(v, Cv);
}

void LinearBulkResidual::residual(SolidAssembler& solid, const SparseMatrix& K,
                                  const std::vector<double>& u, const Constraints& constraints,
                                  DistributedVector& R) {
  const DofDistribution& dist = R.distribution();
  DistributedVector Kv(dist), Cv(dist);
  products(solid, K, u, constraints, true, Kv, Cv);
  const Index first = dist.first_owned_dof(), n = dist.num_owned_dofs();
  double* r = R.owned_values();
  const double *kv = Kv.owned_values(), *cv = Cv.owned_values(), *f0 = f0_.owned_values();
  for (Index i = 0; i < n; ++i)
    r[i] += constraints.is_constrained(first + i) ? kv[i] : -(kv[i] + cv[i] + f0[i]);
}

bool LinearBulkResidual::internal_force(SolidAssembler& solid, const SparseMatrix& K,
                                        const std::vector<double>& u,
                                        const Constraints& constraints, DistributedVector& f) {
  if (!ready() || constraints.values().size() != constrained_.size() ||
      std::any_of(constraints.values().begin(), constraints.values().end(), [&](const auto& kv) {
        return !std::binary_search(constrained_.begin(), constrained_.end(), kv.first);
      }))
    return false;
  const DofDistribution& dist = f.distribution();
  DistributedVector Kv(dist), Cv(dist);
  products(solid, K, u, constraints, false, Kv, Cv);
  double* out = f.owned_values();
  const double *kv = Kv.owned_values(), *cv = Cv.owned_values(), *f0 = f0_.owned_values();
  for (Index i = 0; i < dist.num_owned_dofs(); ++i)
    out[i] += kv[i] + cv[i] + f0[i];
  return true;
}

} // namespace bipot
