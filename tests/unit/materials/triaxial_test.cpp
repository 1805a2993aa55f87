// Drained triaxial compression at a stress point, for mohr_coulomb and drucker_prager (cone
// matched at the compression meridian): axial strain ε_xx driven, lateral total stresses held
// at −p_c by Newton on ε_yy, ε_zz (test::mixed_control), from the isotropic initial stress
// −p_c I. Tension positive: axial σ_a = σ3 < lateral σ_r = σ1 = σ2 = −p_c, q = σ_r − σ_a.
//
// Peak (perfect plasticity, reached exactly once yielding): Mohr–Coulomb
//   (σ1 − σ3) + (σ1 + σ3) sin φ = 2 c cos φ  with σ1 = −p_c, σ3 = −p_c − q
//   ⇒ q_f = 2 (c cos φ + p_c sin φ) / (1 − sin φ).
// The matched cone gives the same q_f (√J2 = q/√3, p = −p_c − q/3).
//
// Dilatancy: MC at the σ1 = σ2 edge flows with Δλ (1 + sin ψ) on each lateral axis and
// −2Δλ (1 − sin ψ) axially: Δεv = 4Δλ sin ψ, Δεq = (2/3)(Δε_r − Δε_a) = (2/3)Δλ (3 − sin ψ),
// so Δεv/Δεq = 6 sin ψ/(3 − sin ψ). DP: Δεp = Δγ (s/(2√J2) + η̄/3 I) gives Δεv = η̄ Δγ,
// Δεq = Δγ/√3, the ratio √3 η̄ = 6 sin ψ/(3 − sin ψ) for the compression match.
#include "materials/drucker_prager.hpp"
#include "materials/mohr_coulomb.hpp"
#include "point_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot {
namespace {

constexpr double E = 3.0e4, nu = 0.3, c = 5.0, phi = 32.0, pc = 100.0;
const double psi = 8.0;

struct Triaxial {
  double q;     // final deviator stress (kPa)
  double ratio; // Δεv^p / Δεq^p over the last step
};

Triaxial run(const Material& m) {
  const int n = 6;
  Voigt sigma0 = Voigt::Zero(n), target = Voigt::Zero(n), strain = Voigt::Zero(n);
  sigma0.head(3).setConstant(-pc);
  target.head(3).setConstant(-pc);
  std::vector<bool> controlled(n, false);
  controlled[1] = controlled[2] = true;
  std::vector<double> state(ElastoPlastic::state_size, 0.0), next(state), previous(state);
  Voigt s;
  for (int step = 1; step <= 60; ++step) { // to ε_a = −3 %, yield near −1 %
    strain(0) = -5e-4 * step;
    s = test::mixed_control(m, strain, controlled, target, sigma0, state.data(), next.data());
    previous = state;
    state = next;
  }
  const double dv = (state[0] + state[1] + state[2]) - (previous[0] + previous[1] + previous[2]);
  const double da = state[0] - previous[0];
  const double dr = 0.5 * (state[1] - previous[1] + state[2] - previous[2]);
  const Voigt total = s + sigma0;
  EXPECT_NEAR(total(1), -pc, 1e-12 * pc);
  EXPECT_NEAR(total(2), -pc, 1e-12 * pc);
  return {total(1) - total(0), dv / (2.0 / 3.0 * (dr - da))};
}

const double sphi = std::sin(phi * M_PI / 180), spsi = std::sin(psi * M_PI / 180);
const double q_peak = 2 * (c * std::cos(phi * M_PI / 180) + pc * sphi) / (1 - sphi);
const double dilatancy = 6 * spsi / (3 - spsi);

TEST(Triaxial, MohrCoulombPeakAndDilatancy) {
  const Triaxial t = run(MohrCoulomb({E, nu, c, phi, psi}));
  EXPECT_NEAR(t.q, q_peak, 1e-8 * q_peak);
  EXPECT_NEAR(t.ratio, dilatancy, 1e-8 * dilatancy);
}

TEST(Triaxial, DruckerPragerPeakAndDilatancy) {
  const Triaxial t = run(DruckerPrager({E, nu, c, phi, psi}));
  EXPECT_NEAR(t.q, q_peak, 1e-8 * q_peak);
  EXPECT_NEAR(t.ratio, dilatancy, 1e-8 * dilatancy);
}

} // namespace
} // namespace bipot
