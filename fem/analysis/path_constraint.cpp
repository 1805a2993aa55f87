// The constraint equation of a path-following increment (PathStep), which borders the
// generalized Newton step of exact_newton_increment.cpp with one row.
#include "fem/analysis/detail/static_analysis_impl.hpp"

namespace bipot {

double PathStep::constraint(const contact::InterfaceNewtonSystem& sys, const Eigen::VectorXd& z,
                            Eigen::VectorXd* grad) const {
  const Index nI = sys.num_dofs(), n = sys.size();
  if (grad) grad->setZero(n + 1);
  if (kind == Kind::ArcLength) {
    // Crisfield's cylindrical arc length: the interface displacements move by L; λ follows.
    // On a debonding snap-back the jumps keep growing while force and head displacement both
    // fall, so they parametrise the path where λ does not. Weighing λ in as well (a sphere)
    // stalled at the corner of a sharp snap-back (the column test: softening 30 times steeper
    // than the elastic unloading), and Riks' normal plane misses a branch that turns back.
    const double norm = z.head(nI).norm();
    if (grad && norm > 0) grad->head(nI) = z.head(nI) / norm;
    return norm - length;
  }
  // Energy released by the interfaces over the step, seen as secant springs from their
  // state at the start: ΔD = W − ΔE with W = −½ (f0 + f)ᵀ x the work done on them and
  // E = −½ fᵀ u their stored energy; zero for an elastic (reversible) step, whatever its
  // size, and growing with every loss of stiffness — the path parameter of a softening
  // branch, on which both force and displacement may decrease.
  const Eigen::VectorXd f = sys.forces();
  if (grad) {
    sys.add_force_gradient(0.5 * u0, *grad);
    grad->head(nI) -= 0.5 * f0;
  }
  return 0.5 * ((f - f0).dot(u0) - f0.dot(z.head(nI))) - dissipation;
}

} // namespace bipot
