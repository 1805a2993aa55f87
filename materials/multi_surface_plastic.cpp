#include "materials/multi_surface_plastic.hpp"

#include "fem/core/error.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace bipot {

namespace {
using Columns = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3>;
using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
} // namespace

double max_yield(const Vec3& stress, double kappa, const std::vector<PrincipalSurface>& surfaces) {
  double f = -std::numeric_limits<double>::infinity();
  for (const auto& s : surfaces)
    f = std::max(f, s.normal.dot(stress) - (s.strength + s.hardening * kappa));
  return f;
}

PrincipalResult principal_return(const Vec3& trial, double kappa,
                                 const std::vector<PrincipalSurface>& surfaces,
                                 const std::vector<ActiveSet>& candidate_sets, double lambda,
                                 double G) {
  const Mat3 C = lambda * Mat3::Ones() + 2 * G * Mat3::Identity();
  // Admissibility tolerances: round-off of the stresses involved.
  double scale = trial.cwiseAbs().maxCoeff();
  for (const auto& s : surfaces)
    scale = std::max(scale, std::abs(s.strength + s.hardening * kappa));
  const double tol = 1e-10 * scale;
  PrincipalResult out;
  for (std::size_t c = 0; c < candidate_sets.size(); ++c) {
    const auto& set = candidate_sets[c].surfaces;
    const int k = static_cast<int>(set.size());
    if (k == 0) continue;
    // Fixed capacity (at most 3 active planes): no heap allocation at quadrature points.
    Columns N(3, k), CM(3, k);
    Small M(k, k);
    SmallVector f(k), w(k), h(k);
    for (int a = 0; a < k; ++a) {
      const PrincipalSurface& s = surfaces[set[a]];
      N.col(a) = s.normal;
      CM.col(a) = C * s.flow;
      f(a) = s.normal.dot(trial) - (s.strength + s.hardening * kappa);
      w(a) = s.hardening_weight;
      h(a) = s.hardening;
    }
    M = N.transpose() * CM + h * w.transpose();
    Eigen::FullPivLU<Small> lu(M);
    lu.setThreshold(1e-12);
    if (lu.rank() < k) continue;
    const SmallVector dl = lu.solve(f);
    if (dl.minCoeff() < -1e-12 * std::max(1.0, dl.cwiseAbs().maxCoeff())) continue;
    const Vec3 sigma = trial - CM * dl;
    // Implied by the yield check for planes like these, but it is the condition under which
    // fixed principal directions are valid, so test it explicitly.
    if (sigma(0) < sigma(1) - tol || sigma(1) < sigma(2) - tol) continue;
    const double dk = w.dot(dl);
    if (max_yield(sigma, kappa + dk, surfaces) > tol) continue;
    out.set = static_cast<int>(c);
    out.stress = sigma;
    out.hardening_increment = dk;
    out.jacobian = Mat3::Identity() - CM * lu.inverse() * N.transpose();
    return out;
  }
  return out;
}

void MultiSurfacePlastic::set_surfaces(std::vector<PrincipalSurface> surfaces,
                                       std::vector<ActiveSet> sets, double apex_stress,
                                       int apex_branch) {
  surfaces_ = std::move(surfaces);
  sets_ = std::move(sets);
  apex_stress_ = apex_stress;
  apex_branch_ = apex_branch;
}

double MultiSurfacePlastic::yield_function(const Mat3& stress, double kappa) const {
  return max_yield(principal(stress).values, kappa, surfaces_);
}

ElastoPlastic::Return MultiSurfacePlastic::return_stress(const Mat3& trial, double kappa) const {
  Return r;
  // Most points of a soil mass stay elastic. Eigen's closed-form eigenvalues are within
  // 1e-8 |σ| of the exact ones, nearly equal ones included (9.2e-9 at worst over 2e6 random
  // tensors, a third of them with two or three eigenvalues 1e-14 to 1 apart), so a trial
  // whose estimate is inside every surface by 1e-6 of the stresses is elastic, and skips the
  // iterative decomposition below (7 % of the Mohr-Coulomb pile's run time). Nearer the
  // surface the exact test decides: the result is the same to the bit.
  {
    Eigen::SelfAdjointEigenSolver<Mat3> direct;
    direct.computeDirect(trial, Eigen::EigenvaluesOnly);
    double scale = trial.norm();
    for (const auto& s : surfaces_)
      scale = std::max(scale, std::abs(s.strength + s.hardening * kappa));
    const Vec3 descending = direct.eigenvalues().reverse();
    if (max_yield(descending, kappa, surfaces_) < -1e-6 * scale) return r;
  }
  const Principal p = principal(trial);
  if (max_yield(p.values, kappa, surfaces_) <= 0.0) return r;
  const PrincipalResult pr =
      principal_return(p.values, kappa, surfaces_, sets_, lame_lambda(), shear_modulus());
  Vec3 s;
  Mat3 J;
  if (pr.set >= 0) {
    r.branch = sets_[pr.set].branch;
    s = pr.stress;
    J = pr.jacobian;
    r.hardening_increment = pr.hardening_increment;
  } else if (std::isfinite(apex_stress_) &&
             p.values.mean() >= apex_stress_ - 1e-10 * p.values.cwiseAbs().maxCoeff()) {
    r.branch = apex_branch_;
    s.setConstant(apex_stress_);
    J.setZero();
  } else {
    std::ostringstream os;
    os.precision(17);
    os << name() << ": no admissible stress return from the trial principal stresses ("
       << p.values(0) << ", " << p.values(1) << ", " << p.values(2) << ") kPa";
    throw SolverError(os.str());
  }
  r.stress = p.directions * s.asDiagonal() * p.directions.transpose();
  r.jacobian = isotropic_jacobian(p, s, J);
  return r;
}

} // namespace bipot
