// The constraint equation of a path-following increment (PathStep), which borders the
// generalized Newton step of exact_newton_increment.cpp with one row.
#include "fem/analysis/detail/path_step.hpp"

namespace bipot {

Eigen::VectorXd on_interface_dofs(const CondensedInterfaceSystem& sys,
                                  const std::vector<double>& u) {
  Eigen::VectorXd v(sys.num_dofs());
  for (Index k = 0; k < sys.num_dofs(); ++k)
    v(k) = u[sys.dofs()[k]];
  return v;
}

double PathStep::constraint(const CondensedInterfaceSystem& sys, const Eigen::VectorXd& z,
                            Eigen::VectorXd* grad) const {
  const Index nI = sys.num_dofs(), n = sys.size();
  if (kind == Kind::ArcLength) {
    if (grad) grad->setZero(n + 1);
    // Crisfield's cylindrical arc length: the interface displacements move by L; λ follows.
    // On a debonding snap-back the jumps keep growing while force and head displacement both
    // fall, so they parametrise the path where λ does not. Weighing λ in as well (a sphere)
    // stalled at the corner of a sharp snap-back (the column test: softening 30 times steeper
    // than the elastic unloading), and Riks' normal plane misses a branch that turns back.
    const Eigen::VectorXd x =
        x_offset.size() == nI ? Eigen::VectorXd(x_offset + z.head(nI)) : z.head(nI);
    const double norm = x.norm();
    if (grad && norm > 0) grad->head(nI) = x / norm;
    return norm - length;
  }
  // The energy adhesion loss releases over the step (Gutiérrez's dissipation control, with
  // the dissipation of the interface law itself rather than a secant estimate): it only
  // grows along a debonding path, also where force and displacement both fall. Friction is
  // left out on purpose: a pile pushed back in dissipates by friction as well, so counting
  // it would let the step run backwards.
  if (grad) grad->setZero(n + 1);
  return sys.released_adhesion_energy(grad) - dissipation;
}

} // namespace bipot
