// The stress returns of the associated, perfectly plastic laws are projections: the closest
// point of the elastic domain to the trial stress in the complementary energy norm
// ‖τ‖² = τ : C⁻¹ : τ. A projection onto a convex set is non-expansive,
//   ‖P(a) − P(b)‖ ≤ ‖a − b‖   for every pair of trial stresses a, b,
// which is a closed-form bound on the return map: no jump between branches (plane, edge,
// apex, cut-off) and no branch that returns to the wrong point. Issue 12: a Newton iteration
// that stalls above round-off on a plastic bulk (the Mohr–Coulomb pile) is not explained by
// a discontinuous return; this test keeps it so. The pairs are drawn near the edges and
// vertices, where the branches meet.
#include "materials/drucker_prager.hpp"
#include "materials/mohr_coulomb.hpp"
#include "materials/stress_tensor.hpp"
#include "materials/tresca.hpp"
#include "materials/von_mises.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace bipot {
namespace {

constexpr double E = 2.5e4, nu = 0.25; // λ = G = 1e4 kPa
constexpr double G = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));

double energy_norm(const Mat3& tau) {
  const double tr = tau.trace();
  return std::sqrt((tau.cwiseProduct(tau).sum() - lambda / (3 * lambda + 2 * G) * tr * tr) /
                   (2 * G));
}

Mat3 returned(const ElastoPlastic& m, const Mat3& trial) {
  const ElastoPlastic::Return r = m.return_stress(trial, 0.0);
  return r.branch == 0 ? trial : r.stress;
}

// A stress with principal values p in random axes; p is drawn around `centre` (kPa) with
// spread `spread`, and with probability 1/2 two of them within 1e-3 `spread` of each other
// (the edges of Mohr–Coulomb and Tresca, σ1 = σ2 or σ2 = σ3).
struct Sampler {
  std::mt19937 rng{12};
  std::normal_distribution<double> normal{0.0, 1.0};
  Mat3 operator()(double centre, double spread) {
    Vec3 p(centre + spread * normal(rng), centre + spread * normal(rng),
           centre + spread * normal(rng));
    const int pair = static_cast<int>(rng() % 4);
    if (pair < 2) p(pair + 1) = p(pair) + 1e-3 * spread * normal(rng);
    const Vec3 axis = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    const Mat3 Q = Eigen::AngleAxisd(M_PI * normal(rng), axis).toRotationMatrix();
    return Q * p.asDiagonal() * Q.transpose();
  }
};

// The largest ratio ‖P(a) − P(b)‖ / ‖a − b‖ over pairs at distances from 1e-6 to 1 times the
// strength: far pairs cross several branches, close pairs probe each boundary.
double worst_ratio(const ElastoPlastic& m, double centre, double strength) {
  Sampler draw;
  double worst = 0.0;
  for (int i = 0; i < 4000; ++i) {
    const Mat3 a = draw(centre, 3 * strength);
    const double h = strength * std::pow(10.0, -6.0 + 6.0 * (i % 7) / 6.0);
    const Mat3 b = a + h * draw(0.0, 1.0);
    const double d = energy_norm(a - b);
    worst = std::max(worst, energy_norm(returned(m, a) - returned(m, b)) / d);
  }
  return worst;
}

TEST(AssociatedReturn, IsNonExpansiveInTheEnergyNorm) {
  const double c = 10.0; // kPa; the Mohr–Coulomb and Drucker–Prager apex is at c cot φ
  const MohrCoulomb mc({E, nu, c, 30.0, 30.0}), mc_cut({E, nu, c, 30.0, 30.0, 5.0});
  const DruckerPrager dp({E, nu, c, 30.0, 30.0});
  const Tresca tresca({E, nu, c});
  const VonMises vm({E, nu, std::sqrt(3.0) * c});
  const double apex = c * std::sqrt(3.0);
  // Round-off of the returns (stresses of about 100 kPa, differences down to 1e-5 kPa).
  const double tol = 1.0 + 1e-6;
  EXPECT_LE(worst_ratio(mc, 0.0, c), tol);
  EXPECT_LE(worst_ratio(mc, apex, c), tol); // around the apex
  EXPECT_LE(worst_ratio(mc_cut, 0.0, c), tol);
  EXPECT_LE(worst_ratio(dp, 0.0, c), tol);
  EXPECT_LE(worst_ratio(dp, apex, c), tol);
  EXPECT_LE(worst_ratio(tresca, 0.0, c), tol);
  EXPECT_LE(worst_ratio(vm, 0.0, c), tol);
}

} // namespace
} // namespace bipot
