// evaluate()'s derivatives on the slip branch at iterates that slide *with* their friction
// force (r_t along Δg_t), which no solution does: there ‖Δg_t‖ is linearised along the slip
// the projection implies, −e with e = τ_t/‖τ_t‖ held (interface_law.cpp), not along Δg_t.
// Checked against central differences of the law with ‖Δg_t‖ replaced by that line through
// its value at the point, written out here from the law's β(jump), μ̄(β) and the cone
// projection; and the exact derivative is shown to differ, so the test sees which one
// evaluate() gives.
#include "contact/laws/coulomb_signorini.hpp"
#include "contact/laws/rccm.hpp"
#include "local_test_utils.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace bipot::contact {
namespace {

using test::fd_jacobian;
using test::relative_error;
using test::vec;

struct Case {
  double beta; ///< committed adhesion
  std::shared_ptr<InterfaceLaw> law;
  LocalVector old_jump, jump, r;
};

TEST(SlipLinearisation, AlongTheSlipTheProjectionImplies) {
  auto coulomb = std::make_shared<CoulombSignorini>(CoulombSignorini::Parameters{0.4});
  auto viscous =
      std::make_shared<Rccm>(Rccm::Parameters{1.0, 1.0, 0.02, 0.6, 0.5}); // β, hence μ̄, moves
  // Δg_t = jump_t − old_t and r_t point the same way: the iterate slides with its force.
  const std::vector<Case> cases = {
      {0.0, coulomb, vec({0.0, 0.0}), vec({-0.05, 0.1}), vec({1.0, 0.8})},
      {0.0, coulomb, vec({0.0, 0.0, 0.0}), vec({-0.05, 0.1, 0.04}), vec({1.0, 0.8, -0.1})},
      {0.7, viscous, vec({0.0, 0.05}), vec({0.1, 0.15}), vec({1.0, 0.3})},
      {0.7, viscous, vec({0.0, 0.05, 0.02}), vec({0.1, 0.15, 0.05}), vec({1.0, 0.3, 0.0})}};
  const double rho = 1.0, dtau = 0.1, h = 1e-7;
  for (const Case& c : cases) {
    const Eigen::Index d = c.jump.size();
    InterfaceState old = initial_state(*c.law, static_cast<int>(d));
    old.beta = c.beta;
    old.jump = c.old_jump;
    InterfaceResponseDerivatives der;
    const InterfaceResponse resp = evaluate(*c.law, old, c.jump, c.r, dtau, rho, &der);
    ASSERT_EQ(resp.status, ContactStatus::Slip);
    const LocalVector e = resp.tau.tail(d - 1).normalized();
    const LocalVector slip0 = c.jump.tail(d - 1) - c.old_jump.tail(d - 1);
    ASSERT_GT(e.dot(slip0), 0.5 * slip0.norm()) << "not the case under test: slides along -e";
    // τ_n = r_n − ρ(g_n + μ̄ (‖Δg_t⁰‖ − e·(Δg_t − Δg_t⁰))), τ_t = r_t − ρ Δg_t,
    // r = Proj_{K_μ̄}(τ), Δg_t⁰ the slip at the point.
    auto piece = [&](const LocalVector& j) {
      const double beta = c.law->update_adhesion(old.beta, j, dtau);
      const double mu_bar = c.law->friction_coefficient(beta);
      const LocalVector slip = j.tail(d - 1) - c.old_jump.tail(d - 1);
      LocalVector tau = c.r;
      tau(0) -= rho * (j(0) + mu_bar * (slip0.norm() - e.dot(slip - slip0)));
      tau.tail(d - 1) -= rho * slip;
      return project_onto_cone(tau, mu_bar).r;
    };
    EXPECT_LE(relative_error(der.dr_djump, fd_jacobian(piece, c.jump, h)), 1e-6);
    auto function = [&](const LocalVector& j) {
      return evaluate(*c.law, old, j, c.r, dtau, rho).r;
    };
    EXPECT_GT(relative_error(der.dr_djump, fd_jacobian(function, c.jump, h)), 1e-2)
        << "the exact derivative would pass too: the case does not tell them apart";
  }
}

} // namespace
} // namespace bipot::contact
