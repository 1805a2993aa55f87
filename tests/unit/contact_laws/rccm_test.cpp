// RCCM against the closed forms of docs/formulation.md §3: monotonic opening and shear (traction,
// peak, work of separation = w), irreversibility, viscous adhesion vs an independent RK4
// integration, and the β0 = 0 reduction to Coulomb–Signorini.
#include "contact/laws/coulomb_signorini.hpp"
#include "contact/laws/rccm.hpp"
#include "local_test_utils.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace bipot::contact {
namespace {

using test::vec;

// Pile-soil-like values: C_n = 1e6 kN/m³, C_t = 4e5 kN/m³, w = 0.05 kJ/m².
constexpr double kCn = 1e6, kCt = 4e5, kW = 0.05;
constexpr double kRho = 1e6; // kPa/m, of the order of the stiffnesses

/// Quasi-static monotonic loading along jump(g) = g·direction, from g = 0 to g_max in n steps,
/// with r = 0 given to evaluate() (the law's solution when nothing presses the faces: feeding
/// back old.r would only accumulate rounding noise over the 50000 steps). Returns
/// the magnitude of the traction's component along `direction` at each g_i = g_max·i/n.
struct Curve {
  std::vector<double> g, t;
};

Curve monotonic(const Rccm& law, const LocalVector& direction, double g_max, int n) {
  InterfaceState old = initial_state(law, static_cast<int>(direction.size()));
  Curve c{{0.0}, {0.0}};
  for (int i = 1; i <= n; ++i) {
    const double g = g_max * (static_cast<double>(i) / n);
    const LocalVector jump = g * direction;
    const LocalVector zero = LocalVector::Zero(direction.size());
    const auto resp = evaluate(law, old, jump, zero, 0.0, kRho);
    EXPECT_LE(resp.beta, old.beta); // never heals
    // In shear g_n = 0: grazing contact, where the open/slip test is an equality decided by the
    // rounding of ρμ̄‖Δg_t‖, so r is 0 up to a few ulps of ρ‖Δg_t‖.
    EXPECT_LE(resp.r.norm(), 1e-14 * kRho * g_max / n);
    c.g.push_back(g);
    c.t.push_back(-resp.traction.dot(direction));
    old = InterfaceState{resp.beta, jump, resp.r};
  }
  return c;
}

/// Closed form for monotonic loading with stiffness C, from β0 = 1 (docs/formulation.md §3).
double closed_form(double g, double stiffness) {
  const double g_star = std::sqrt(kW / stiffness);
  return g <= g_star ? stiffness * g : kW * kW / (stiffness * g * g * g);
}

void check_monotonic(const LocalVector& direction, double stiffness) {
  const Rccm law({kCn, kCt, kW, 0.5});
  const double g_star = std::sqrt(kW / stiffness);
  // 1000 steps up to g* (a grid point up to rounding), on to 50 g*.
  const int per_gstar = 1000, n = 50 * per_gstar;
  const Curve c = monotonic(law, direction, 50.0 * g_star, n);
  double peak = 0.0, work = 0.0;
  for (std::size_t i = 0; i < c.g.size(); ++i) {
    // The computed traction is β²C g with β = w/(C g²) evaluated in a few roundings: 1e-12.
    EXPECT_NEAR(c.t[i], closed_form(c.g[i], stiffness), 1e-12 * closed_form(c.g[i], stiffness))
        << "g = " << c.g[i];
    peak = std::max(peak, c.t[i]);
    if (i > 0) work += 0.5 * (c.t[i] + c.t[i - 1]) * (c.g[i] - c.g[i - 1]);
  }
  // Peak at g* (a grid point): C g* = √(w C) up to rounding.
  EXPECT_NEAR(peak, std::sqrt(kW * stiffness), 1e-12 * std::sqrt(kW * stiffness));
  // Analytical tail ∫_G^∞ w²/(C g³) dg = w²/(2 C G²).
  const double g_end = c.g.back();
  work += kW * kW / (2.0 * stiffness * g_end * g_end);
  // Trapezoid error ~ h²/12 ∫|t''| ≈ 1e-7 w with h = g*/1000; 0.1% is the brief's tolerance.
  EXPECT_NEAR(work, kW, 1e-3 * kW);
}

TEST(Rccm, MonotonicOpeningMatchesClosedForm) {
  check_monotonic(vec({1.0, 0.0}), kCn);
  check_monotonic(vec({1.0, 0.0, 0.0}), kCn);
}

TEST(Rccm, MonotonicShearMatchesClosedForm) {
  check_monotonic(vec({0.0, 1.0}), kCt);
  check_monotonic(vec({0.0, -1.0}), kCt);
  check_monotonic(vec({0.0, 0.6, -0.8}), kCt);
}

TEST(Rccm, MixedModeQuasiStaticAdhesion) {
  // β = min(β_old, w/E), E = C_n⟨g_n⟩₊² + C_t‖g_t‖²; a closing jump does not count in E.
  const Rccm law({kCn, kCt, kW});
  const LocalVector jump = vec({3e-4, 2e-4, -1e-4});
  const double energy = kCn * 9e-8 + kCt * 5e-8;
  // One division: a couple of ulps.
  EXPECT_NEAR(law.update_adhesion(1.0, jump, 0.0), kW / energy, 1e-15);
  EXPECT_EQ(law.update_adhesion(0.1, jump, 0.0), 0.1);   // already more damaged: unchanged
  const LocalVector closing = vec({-3e-4, 4e-4, -3e-4}); // E = C_t·2.5e-7 = 0.1 = 2 w
  EXPECT_NEAR(law.update_adhesion(1.0, closing, 0.0), 0.5, 1e-15);
  EXPECT_EQ(law.update_adhesion(1.0, vec({-1.0, 0.0}), 0.0), 1.0); // E = 0
}

TEST(Rccm, IrreversibleUnloadingIsLinearWithDamagedStiffness) {
  const Rccm law({kCn, kCt, kW});
  const double g_star = std::sqrt(kW / kCn);
  // Open to 3 g*, unload to 1.5 g* and back to 0, reload to 3 g*, continue to 5 g*.
  std::vector<double> path;
  auto leg = [&](double from, double to, int n) {
    for (int i = 1; i <= n; ++i)
      path.push_back(from + (to - from) * i / n);
  };
  leg(0.0, 3.0, 300);
  leg(3.0, 1.5, 150);
  leg(1.5, 0.0, 150);
  leg(0.0, 3.0, 300);
  leg(3.0, 5.0, 200);

  InterfaceState old = initial_state(law, 2);
  double g_max = 0.0;
  for (double x : path) {
    const double g = x * g_star;
    const LocalVector jump = vec({g, 0.0});
    const auto resp = evaluate(law, old, jump, vec({0.0, 0.0}), 0.0, kRho);
    ASSERT_LE(resp.beta, old.beta) << "beta increased at g = " << g;
    g_max = std::max(g_max, g);
    // Damage set by the largest opening so far: β = min(1, w/(C_n g_max²)); the traction is
    // linear with the damaged stiffness β² C_n. Few roundings of O(1) quantities: 1e-12.
    const double beta = std::min(1.0, kW / (kCn * g_max * g_max));
    EXPECT_NEAR(resp.beta, beta, 1e-12 * beta);
    const double expected = -beta * beta * kCn * g;
    EXPECT_NEAR(resp.traction(0), expected, 1e-12 * std::abs(expected) + 1e-300);
    old = InterfaceState{resp.beta, jump, resp.r};
  }
}

// Implicit-Euler adhesion under the opening g(τ) = v τ (nondimensional C_n = w = α = v = 1)
// against RK4 of α β̇ = −⟨C_n g² β − w⟩₊ with a step 1e-5, whose own accuracy is checked
// in the test by comparing with RK4 at twice the step.
double rk4_beta(double t_end, double h) {
  auto f = [](double t, double b) { return -std::max(t * t * b - 1.0, 0.0); };
  const int n = static_cast<int>(std::lround(t_end / h));
  double b = 1.0;
  for (int i = 0; i < n; ++i) {
    const double t = i * h;
    const double k1 = f(t, b), k2 = f(t + h / 2, b + h / 2 * k1), k3 = f(t + h / 2, b + h / 2 * k2),
                 k4 = f(t + h, b + h * k3);
    b += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return b;
}

double implicit_euler_beta(const Rccm& law, double t_end, double dtau) {
  InterfaceState old = initial_state(law, 2);
  const int n = static_cast<int>(std::lround(t_end / dtau));
  for (int i = 1; i <= n; ++i) {
    const LocalVector jump = vec({i * dtau, 0.0});
    const auto resp = evaluate(law, old, jump, vec({0.0, 0.0}), dtau, 1.0);
    EXPECT_LE(resp.beta, old.beta);
    old = InterfaceState{resp.beta, jump, resp.r};
  }
  return old.beta;
}

TEST(Rccm, ViscousAdhesionConvergesAtFirstOrderToRk4) {
  const Rccm law({1.0, 1.0, 1.0, 0.0, 1.0});
  const double t_end = 3.0; // onset at τ = 1; β(3) ≈ 0.122, well above the rate-free 1/9
  const double reference = rk4_beta(t_end, 1e-5);
  // RK4 is 4th order except for one kink (β̇ switching on): halving 2e-5 → 1e-5 changes β by
  // ~1e-15, so the reference is far more accurate than the 1e-5..1e-4 errors measured below.
  EXPECT_LT(std::abs(rk4_beta(t_end, 2e-5) - reference), 1e-10);
  EXPECT_GT(reference, 1.0 / 9.0 + 5e-3); // viscosity matters here
  std::vector<double> errors;
  for (double dtau : {0.01, 0.005, 0.0025, 0.00125})
    errors.push_back(std::abs(implicit_euler_beta(law, t_end, dtau) - reference));
  // Implicit Euler is first order: error ~1.6e-5 at the finest step (brief: < 1e-3).
  EXPECT_LT(errors.back(), 1e-3);
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double ratio = errors[i - 1] / errors[i];
    // Asymptotic ratio 2; the O(Δτ²) remainder moves it by ~1.5% at the coarsest step.
    EXPECT_GT(ratio, 1.9);
    EXPECT_LT(ratio, 2.1);
  }
}

TEST(Rccm, QuasiStaticIsTheZeroViscosityLimit) {
  // With α → 0 the implicit update tends to min(β, w/E): α = 1e-9 agrees to ~α/Δτ relative.
  const Rccm viscous({kCn, kCt, kW, 0.3, 1e-9}), quasi({kCn, kCt, kW, 0.3, 0.0});
  const LocalVector jump = vec({4e-4, 1e-4, 2e-4});
  EXPECT_NEAR(viscous.update_adhesion(0.9, jump, 1.0), quasi.update_adhesion(0.9, jump, 1.0), 1e-6);
}

TEST(Rccm, FrictionCoefficientGrowsAsAdhesionIsLost) {
  const Rccm law({kCn, kCt, kW, 0.6});
  for (double beta : {0.0, 0.25, 1.0}) {
    EXPECT_NEAR(law.friction_coefficient(beta), 0.6 * (1.0 - beta), 1e-15); // one rounding
    EXPECT_EQ(law.friction_coefficient_dbeta(beta), -0.6);
  }
  EXPECT_EQ(law.stiffness_scale(), kCn);
  EXPECT_EQ(law.initial_adhesion(), 1.0);
}

TEST(Rccm, WithoutAdhesionEqualsCoulombSignorini) {
  const double mu = 0.45;
  const Rccm rccm({kCn, kCt, kW, mu, 0.0, 0.0});
  const CoulombSignorini cs({mu});
  struct Case {
    LocalVector old_jump, jump, r;
  };
  const std::vector<Case> cases = {
      {vec({0.0, 0.0}), vec({1e-3, 2e-4}), vec({0.0, 0.0})},     // open
      {vec({0.0, 0.0}), vec({1e-3, 2e-4}), vec({0.5, 0.1})},     // open, pressed
      {vec({0.0, 1e-3}), vec({0.0, 1e-3}), vec({2.0, 0.3})},     // stick
      {vec({0.0, 1e-3}), vec({-1e-4, 1.5e-3}), vec({2.0, 0.3})}, // slip
      {vec({0.0, 0.0, 0.0}), vec({2e-4, -1e-4, 3e-4}), vec({0.0, 0.0, 0.0})},
      {vec({0.0, 1e-3, 0.0}), vec({0.0, 1e-3, 0.0}), vec({1.0, 0.2, -0.1})},
      {vec({0.0, 1e-3, 0.0}), vec({-2e-4, 2e-3, 1e-3}), vec({1.0, 0.2, -0.1})}};
  for (const auto& c : cases) {
    for (double rho : {1e2, 1e4}) {
      InterfaceState old_rccm = initial_state(rccm, static_cast<int>(c.jump.size()));
      InterfaceState old_cs = initial_state(cs, static_cast<int>(c.jump.size()));
      EXPECT_EQ(old_rccm.beta, 0.0);
      old_rccm.jump = old_cs.jump = c.old_jump;
      InterfaceResponseDerivatives d1, d2;
      const auto a = evaluate(rccm, old_rccm, c.jump, c.r, 0.1, rho, &d1);
      const auto b = evaluate(cs, old_cs, c.jump, c.r, 0.1, rho, &d2);
      // Same arithmetic on both sides (β² C g = 0): equal to 1e-15 as the brief asks.
      EXPECT_EQ(a.status, b.status);
      EXPECT_EQ(a.beta, 0.0);
      EXPECT_NEAR(a.mu_bar, b.mu_bar, 1e-15);
      EXPECT_LE((a.r - b.r).norm(), 1e-15);
      EXPECT_LE((a.traction - b.traction).norm(), 1e-15);
      EXPECT_LE((d1.dt_djump - d2.dt_djump).norm(), 1e-15 * (1.0 + d2.dt_djump.norm()));
      EXPECT_LE((d1.dt_dr - d2.dt_dr).norm(), 1e-15);
    }
  }
}

} // namespace
} // namespace bipot::contact
