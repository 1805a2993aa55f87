#include "materials/material_registry.hpp"
#include "materials/von_mises.hpp"
#include "point_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot {
namespace {

using test::fd_tangent;
using test::mixed_control;
using test::relative_difference;

constexpr double E = 2.0e5, nu = 0.3, sy = 250.0, H = 1.0e4;

// Uniaxial stress, strain-controlled in xx, the other stresses held at zero. Closed form:
// σ = E ε while elastic; after yield σ = σ_y + H εp and ε = σ/E + εp give
// σ = σ_y + E H/(E + H) (ε − σ_y/E), and the equivalent plastic strain is εp = (σ − σ_y)/H.
// Newton stops at a stress residual of 1e-13 relative, so 1e-10 is round-off plus margin.
TEST(VonMises, UniaxialHardeningCurveMatchesClosedForm) {
  VonMises m({E, nu, sy, H});
  for (int n : {4, 6}) {
    std::vector<bool> controlled(n, false);
    controlled[1] = controlled[2] = true; // σ_yy = σ_zz = 0 (in 2D: axisymmetric-like control)
    std::vector<double> state(ElastoPlastic::state_size, 0.0), next(state);
    Voigt strain = Voigt::Zero(n), target = Voigt::Zero(n), sigma0 = Voigt::Zero(n);
    for (int step = 1; step <= 20; ++step) {
      const double eps = step * 0.25 * sy / E; // up to 5 ε_y
      strain(0) = eps;
      const Voigt s =
          mixed_control(m, strain, controlled, target, sigma0, state.data(), next.data());
      state = next;
      const double expected = eps <= sy / E ? E * eps : sy + E * H / (E + H) * (eps - sy / E);
      EXPECT_NEAR(s(0), expected, 1e-10 * expected) << "n=" << n << " step " << step;
      const double ep = std::max(0.0, (expected - sy) / H);
      EXPECT_NEAR(state[ElastoPlastic::equivalent_plastic_strain_slot], ep, 1e-10 * sy / E);
      EXPECT_NEAR(state[ElastoPlastic::hardening_slot], ep, 1e-10 * sy / E);
    }
  }
}

// Simple shear γ on top of an initial stress σ0 = −100 I + 20 (e_x⊗e_y + e_y⊗e_x):
// trial σ_xy = 20 + G γ, q_trial = √3 |σ_xy|, Δγ = (q_trial − σ_y)/(3G + H) and the
// returned total shear is σ_xy (1 − 3G Δγ/q_trial); the hydrostatic part is untouched.
TEST(VonMises, RadialReturnInSimpleShearWithInitialStress) {
  VonMises m({E, nu, sy, H});
  const double G = E / (2 * (1 + nu)), gamma = 5e-3;
  const double tr = 20 + G * gamma, q = std::sqrt(3.0) * tr;
  const double dg = (q - sy) / (3 * G + H);
  const double total = tr * (1 - 3 * G * dg / q);
  for (int n : {4, 6}) {
    Voigt strain = Voigt::Zero(n), sigma0 = Voigt::Zero(n);
    strain(3) = gamma;
    sigma0 << -100, -100, -100, 20, Voigt::Zero(n - 4);
    Voigt s;
    VoigtMatrix D;
    std::vector<double> next(ElastoPlastic::state_size);
    m.update(strain, sigma0, nullptr, s, D, next.data());
    EXPECT_NEAR(s(3), total - 20, 1e-10 * total);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(s(i), 0.0, 1e-10 * total);
    EXPECT_NEAR(next[ElastoPlastic::hardening_slot], dg, 1e-10 * dg);
    EXPECT_NEAR(next[ElastoPlastic::equivalent_plastic_strain_slot], dg, 1e-10 * dg);
    // The returned total stress is on the hardened yield surface.
    EXPECT_NEAR(m.yield_function(stress_tensor(s + sigma0), dg), 0.0, 1e-10 * sy);
    EXPECT_EQ(next[ElastoPlastic::plastic_flag_slot], 1.0);
  }
}

// The consistent tangent against central differences (step 1e-8 on strains ~1e-3: truncation
// ~1e-10, round-off ~1e-9 relative), from a hardened state, in 2D and 3D, elastic and plastic.
TEST(VonMises, ConsistentTangentMatchesFiniteDifferences) {
  VonMises m({E, nu, sy, H});
  for (int n : {4, 6}) {
    Voigt e1(n), sigma0 = Voigt::Zero(n);
    if (n == 4)
      e1 << 2.1e-3, -0.7e-3, 0.3e-3, 1.3e-3;
    else
      e1 << 2.1e-3, -0.7e-3, 0.3e-3, 1.3e-3, -0.4e-3, 0.9e-3;
    sigma0.head(3).setConstant(-50.0);
    std::vector<double> s0(ElastoPlastic::state_size), s1(ElastoPlastic::state_size);
    Voigt s;
    VoigtMatrix D;
    m.update(e1, sigma0, nullptr, s, D, s0.data()); // first plastic step
    ASSERT_EQ(s0[ElastoPlastic::plastic_flag_slot], 1.0);
    for (double scale : {1.3, 0.99}) { // further loading (plastic), unloading (elastic)
      const Voigt e2 = scale * e1;
      m.update(e2, sigma0, s0.data(), s, D, s1.data());
      const VoigtMatrix fd = fd_tangent(m, e2, sigma0, s0.data(), 1e-8);
      EXPECT_LT(relative_difference(D, fd), 1e-6) << "n=" << n << " scale " << scale;
      EXPECT_EQ(s1[ElastoPlastic::plastic_flag_slot], scale > 1 ? 1.0 : 0.0);
    }
  }
}

// Purity: update() never writes old_state; the state advances only when the caller copies
// new_state, so repeating an update from the same old state gives the same result.
TEST(VonMises, OldStateIsNeverWritten) {
  VonMises m({E, nu, sy, H});
  Voigt strain(6), sigma0 = Voigt::Zero(6);
  strain << 3e-3, -1e-3, -1e-3, 2e-3, 0, 0;
  std::vector<double> old(ElastoPlastic::state_size, 0.0), copy = old, n1(old.size()),
                                                           n2(old.size());
  Voigt s1, s2;
  VoigtMatrix D;
  m.update(strain, sigma0, old.data(), s1, D, n1.data());
  EXPECT_EQ(old, copy);
  m.update(strain, sigma0, old.data(), s2, D, n2.data());
  EXPECT_EQ(n1, n2);
  EXPECT_EQ((s1 - s2).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(n1[ElastoPlastic::equivalent_plastic_strain_slot], 0.0);
  double values[2];
  m.output(n1.data(), values);
  EXPECT_EQ(values[0], n1[ElastoPlastic::equivalent_plastic_strain_slot]);
  EXPECT_EQ(values[1], 1.0);
  EXPECT_EQ(m.output_field_name(0), "equivalent_plastic_strain");
}

TEST(VonMises, RegistryCreatesItAndRejectsZeroYieldStress) {
  ParameterSet p;
  p.set("youngs_modulus", E);
  p.set("poissons_ratio", nu);
  p.set("yield_stress", 0.0);
  try {
    builtin_materials().create("von_mises", p);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("von_mises.yield_stress: value 0 is out of range"),
              std::string::npos)
        << e.what();
  }
  p.set("yield_stress", sy);
  EXPECT_EQ(builtin_materials().create("von_mises", p)->num_state_variables(),
            ElastoPlastic::state_size);
}

} // namespace
} // namespace bipot
