// The fixed points of r ↦ Proj_{K_μ̄}(predictor(r)) are exactly the states satisfying the
// contact law of docs/formulation.md §3 (open, closed stick, closed slip), for any ρ > 0.
#include "contact/laws/coulomb_cone.hpp"
#include "contact/laws/coulomb_signorini.hpp"
#include "contact/laws/interface_law.hpp"
#include "local_test_utils.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace bipot::contact {
namespace {

using test::vec;

LocalVector map(const LocalVector& r, double g_n, const LocalVector& slip_inc, double mu,
                double rho) {
  return project_onto_cone(bipotential_predictor(r, g_n, slip_inc, mu, rho), mu).r;
}

// Tractions O(1) kPa, jumps O(1e-3) m; ρ spans six decades so ρ·jump ranges from 1e-4 to 1e2
// of the traction. The map reproduces r up to a few roundings of the largest term: 1e-12.
const std::vector<double> kRhos = {0.1, 10.0, 1e3, 1e5};
constexpr double kFixedTol = 1e-12;
// A state violating the law moves by at least ~min(ρ)·1e-3 = 1e-4 in these cases.
constexpr double kMovesAtLeast = 1e-6;

struct State {
  LocalVector r;
  double g_n;
  LocalVector slip_inc;
  double mu;
};

std::vector<State> lawful_states() {
  std::vector<State> s;
  for (double mu : {0.0, 0.4, 1.5}) {
    // Open: g_n > 0, r = 0, any slip.
    s.push_back({vec({0.0, 0.0}), 2e-3, vec({1e-3}), mu});
    s.push_back({vec({0.0, 0.0, 0.0}), 1e-3, vec({-2e-3, 5e-4}), mu});
    // Grazing: g_n = 0, r = 0, slipping freely.
    s.push_back({vec({0.0, 0.0, 0.0}), 0.0, vec({1e-3, 1e-3}), mu});
    // Closed stick: g_n = 0, Δg_t = 0, ‖r_t‖ ≤ μ̄ p (inside, and on the boundary).
    s.push_back({vec({2.0, 0.5 * mu * 2.0}), 0.0, vec({0.0}), mu});
    s.push_back({vec({2.0, 0.6 * mu * 2.0, -0.8 * mu * 2.0}), 0.0, vec({0.0, 0.0}), mu});
    s.push_back({vec({1.0, 0.1 * mu, 0.2 * mu}), 0.0, vec({0.0, 0.0}), mu});
    // Closed slip: g_n = 0, r_t = −μ̄ p Δg_t/‖Δg_t‖.
    s.push_back({vec({3.0, -mu * 3.0}), 0.0, vec({2e-3}), mu});
    s.push_back({vec({1.5, mu * 1.5}), 0.0, vec({-1e-3}), mu});
    s.push_back({vec({2.0, -0.6 * mu * 2.0, 0.8 * mu * 2.0}), 0.0, vec({3e-3, -4e-3}), mu});
  }
  return s;
}

TEST(BipotentialFixedPoint, LawfulStatesAreFixedPoints) {
  for (const auto& st : lawful_states()) {
    for (double rho : kRhos) {
      const LocalVector r = map(st.r, st.g_n, st.slip_inc, st.mu, rho);
      EXPECT_LE((r - st.r).norm(), kFixedTol * (1.0 + st.r.norm()))
          << "r = " << st.r.transpose() << ", g_n = " << st.g_n << ", mu = " << st.mu
          << ", rho = " << rho << " -> " << r.transpose();
    }
  }
}

TEST(BipotentialFixedPoint, StatesViolatingTheLawAreNotFixedPoints) {
  const double mu = 0.4;
  const std::vector<State> bad = {
      {vec({1.0, 0.0}), 2e-3, vec({0.0}), mu},                // open but pressed
      {vec({0.0, 0.0}), -1e-3, vec({0.0}), mu},               // interpenetration, no pressure
      {vec({-1.0, 0.0, 0.0}), 0.0, vec({0.0, 0.0}), mu},      // adhesive (negative) pressure
      {vec({2.0, 0.1}), 0.0, vec({1e-3}), mu},                // slipping below the cone limit
      {vec({2.0, mu * 2.0}), 0.0, vec({1e-3}), mu},           // friction aiding the slip
      {vec({2.0, 0.0, mu * 2.0}), 0.0, vec({1e-3, 0.0}), mu}, // friction not opposing slip
      {vec({2.0, 1.5 * mu * 2.0}), 0.0, vec({0.0}), mu},      // outside the cone, sticking
      {vec({2.0, 0.3}), 0.0, vec({1e-3}), 0.0},               // frictionless with friction
  };
  for (const auto& st : bad) {
    for (double rho : kRhos) {
      const LocalVector r = map(st.r, st.g_n, st.slip_inc, st.mu, rho);
      EXPECT_GT((r - st.r).norm(), kMovesAtLeast)
          << "r = " << st.r.transpose() << ", g_n = " << st.g_n << ", rho = " << rho;
    }
  }
}

TEST(BipotentialFixedPoint, EvaluateReproducesTheFixedPointWithSlipFromTheOldState) {
  // Through evaluate(): Δg_t = jump_t − old.jump_t, closed slip under Coulomb–Signorini.
  const CoulombSignorini law({0.5});
  InterfaceState old = initial_state(law, 3);
  old.jump = vec({0.0, 1e-3, 1e-3});
  const LocalVector jump = vec({0.0, 1e-3 + 3e-4, 1e-3 - 4e-4}); // Δg_t = (3, −4)·1e-4
  const LocalVector r = vec({2.0, -0.6, 0.8});                   // −0.5·2·(0.6, −0.8)
  for (double rho : kRhos) {
    const auto resp = evaluate(law, old, jump, r, 1.0, rho);
    EXPECT_EQ(resp.status, ContactStatus::Slip);
    EXPECT_LE((resp.r - r).norm(), kFixedTol * 3.0);
    EXPECT_LE((resp.traction - r).norm(), kFixedTol * 3.0); // no adhesive part
  }
}

} // namespace
} // namespace bipot::contact
