// The operations on an increment's system that the increment solvers share (IncrementContext).
#include "fem/analysis/detail/increment_context.hpp"

#include "fem/linalg/communicator.hpp"

#include <algorithm>
#include <cmath>

namespace bipot {

void IncrementContext::set_step_loads(double lambda) {
  F_step.copy(F_prev);
  F_step.scale(1.0 - lambda);
  F_step.axpy(lambda, F_cur);
}

void IncrementContext::begin_increment(double lambda) {
  set_step_loads(lambda);
  for (std::size_t k = 0; k < interfaces.size(); ++k) {
    interfaces[k]->set_gap_shift(gap_start[k] + lambda * (gap_target[k] - gap_start[k]));
    interfaces[k]->begin_increment(extrapolation);
  }
  move_obstacles(lambda);
}

void IncrementContext::add_step_loads(const Constraints& constraints) {
  const Index first = dist.first_owned_dof();
  double* r = R.owned_values();
  const double* f = F_step.owned_values();
  for (Index i = 0; i < dist.num_owned_dofs(); ++i)
    if (!constraints.is_constrained(first + i)) r[i] += f[i];
}

// The first pass of an increment puts diag(K) × the prescribed increment on the constrained
// rows, which is no force on the body: on a footing it was 65 times the reactions, and the
// increment's relative tolerance as much looser.
double IncrementContext::free_norm(const DistributedVector& v,
                                   const Constraints& constraints) const {
  const Index first = dist.first_owned_dof();
  const double* x = v.owned_values();
  double sum = 0;
  for (Index i = 0; i < dist.num_owned_dofs(); ++i)
    if (!constraints.is_constrained(first + i)) sum += x[i] * x[i];
  return std::sqrt(sum_all(sum));
}

double IncrementContext::residual_norm(const std::vector<double>& trial, double dtau,
                                       const Constraints& constraints) {
  R.set_zero();
  solid.residual(trial, constraints, R);
  for (const auto& ia : interfaces) {
    ia->evaluate(trial, dtau);
    ia->add_to_system(constraints, nullptr, R);
  }
  R.finish_assembly();
  add_step_loads(constraints);
  return R.norm2();
}

std::vector<bool> IncrementContext::prescribed() const {
  std::vector<bool> flags(u.size());
  for (const auto& kv : target)
    flags[kv.first] = true;
  return flags;
}

Constraints IncrementContext::held() const {
  Constraints fixed;
  for (const auto& kv : target)
    fixed.set(kv.first, 0.0);
  return fixed;
}

double IncrementContext::interface_force_scale() const {
  double scale = 0;
  for (const auto& ia : interfaces)
    scale = std::max(scale, ia->force_scale());
  return scale;
}

double IncrementContext::interface_roundoff() const {
  double roundoff = 0;
  for (const auto& ia : interfaces)
    roundoff = std::max(roundoff, ia->roundoff_force());
  return roundoff;
}

} // namespace bipot
