#include "materials/drucker_prager.hpp"
#include "materials/material_registry.hpp"
#include "point_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot {
namespace {

using test::expect_fd_tangent;
using test::expect_return;

// E = 2.5e4 kPa, ν = 0.25: G = 1e4, K = E/(3(1 − 2ν)) = 5e4/3 kPa. c = 10 kPa, φ = 30°,
// sin ψ = 0.2. Compression match: η = 6 sin φ/(√3 (3 − sin φ)) = 3/(2.5√3) ≈ 0.6928,
// ξ = 6 cos φ/(√3 (3 − sin φ)) = 1.2, η̄ = 6 sin ψ/(√3 (3 − sin ψ)) = 1.2/(2.8√3) ≈ 0.2474.
constexpr double E = 2.5e4, nu = 0.25, c = 10.0, phi = 30.0, G = 1e4, K = 5e4 / 3;
const double psi = std::asin(0.2) * 180.0 / M_PI;
const double eta = 6 * 0.5 / (std::sqrt(3.0) * 2.5),
             xi = 6 * std::cos(M_PI / 6) / (std::sqrt(3.0) * 2.5);
const double eta_bar = 6 * 0.2 / (std::sqrt(3.0) * 2.8);

// Trial (−20, −50, −150): p* = −220/3, s* = (160, 70, −230)/3, √J2* = sqrt(s*:s*/2) ≈ 68.07,
// f* ≈ 5.27 > 0. Face return (de Souza Neto et al. 2008, eq. 8.91):
// Δγ = f*/(G + K η η̄), p = p* − K η̄ Δγ, s = (1 − G Δγ/√J2*) s*; here G Δγ ≈ 4.1 < √J2*.
TEST(DruckerPrager, ConeReturnAndNonAssociatedFlow) {
  DruckerPrager m({E, nu, c, phi, psi});
  const Vec3 t(-20, -50, -150);
  const double p = t.sum() / 3, j = std::sqrt(0.5 * (t.array() - p).square().sum());
  const double f = j + eta * p - xi * c;
  const double dg = f / (G + K * eta * eta_bar);
  const Vec3 s =
      (p - K * eta_bar * dg) * Vec3::Ones() + (1 - G * dg / j) * (t.array() - p).matrix();
  expect_return(m, t, s, DruckerPrager::Cone);
  // Plastic strain increment = Δγ ∂g/∂σ = Δγ (s/(2√J2) + η̄/3 I), not ∂f/∂σ.
  Voigt sigma0(6), out;
  sigma0 << t, 0, 0, 0;
  double state[ElastoPlastic::state_size];
  VoigtMatrix D;
  m.update(Voigt::Zero(6), sigma0, nullptr, out, D, state);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(state[i], dg * ((t(i) - p) / (2 * j) + eta_bar / 3), 1e-10 * dg);
}

// Trial (40, 35, 30): p* = 35, √J2* = 5, Δγ = f*/(G + K η η̄) gives G Δγ ≈ 13 > 5: apex,
// σ = ξ c/η I = c cot φ I = 10√3 I.
TEST(DruckerPrager, ApexReturn) {
  DruckerPrager m({E, nu, c, phi, psi});
  expect_return(m, Vec3(40, 35, 30), Vec3::Constant(10 * std::sqrt(3.0)), DruckerPrager::Apex);
  expect_return(DruckerPrager({E, nu, c, phi, 0.0}), Vec3(40, 35, 30),
                Vec3::Constant(10 * std::sqrt(3.0)), DruckerPrager::Apex);
}

TEST(DruckerPrager, ConsistentTangent) {
  DruckerPrager m({E, nu, c, phi, psi});
  expect_fd_tangent(m, Vec3(-20, -50, -150), DruckerPrager::Cone);
  expect_fd_tangent(m, Vec3(40, 35, 30), DruckerPrager::Apex);
  expect_fd_tangent(m, Vec3(-90, -100, -110), DruckerPrager::Elastic);
}

// The cone passes through Mohr–Coulomb's compression meridian (σ1 = σ2 > σ3) or its
// extension meridian (σ1 > σ2 = σ3) as `match` says: MC failure states with σ3 (resp. σ2,
// σ3) = −100 kPa: compression σ1 = (2c cos φ + σ3 (1 − sin φ))/(1 + sin φ) on two axes,
// extension the same σ1 on one axis.
TEST(DruckerPrager, ConeMatchesMohrCoulombMeridians) {
  const double s3 = -100, s1 = (2 * c * std::cos(M_PI / 6) + s3 * 0.5) / 1.5;
  const DruckerPrager comp({E, nu, c, phi, phi, DruckerPrager::Match::Compression});
  const DruckerPrager ext({E, nu, c, phi, phi, DruckerPrager::Match::Extension});
  EXPECT_NEAR(comp.yield_function(Vec3(s1, s1, s3).asDiagonal().toDenseMatrix(), 0), 0,
              1e-12 * 100);
  EXPECT_NEAR(ext.yield_function(Vec3(s1, s3, s3).asDiagonal().toDenseMatrix(), 0), 0, 1e-12 * 100);
}

// Plane-strain match, associated (ψ = φ). In steady plastic flow the stress is stationary,
// so the strain rate is all plastic, ∝ ∂f/∂σ = s/(2√J2) + η/3 I, and ε̇_zz = 0 forces
// s_zz = −2√J2 η/3. With s_xx = s_yy (hence s_xx = √J2 η/3) and τ = s_xy, J2 = J2 η²/3 + τ²:
// the rate is (η/2, η/2, 0, γ̇ = sqrt(1 − η²/3)) per unit Δγ. Driven along it from −100 I
// the stress tends exponentially (rate ~ G/strength per unit strain) to that state, whose
// in-plane principal stresses (centre p + √J2 η/3, radius τ) satisfy Mohr–Coulomb,
// (σ1 − σ3) + (σ1 + σ3) sin φ = 2c cos φ: the defining property of the match.
TEST(DruckerPrager, PlaneStrainMatchGivesMohrCoulombPlaneStrainStrength) {
  const DruckerPrager m({E, nu, c, phi, phi, DruckerPrager::Match::PlaneStrain});
  const double t = std::tan(M_PI / 6), eta_ps = 3 * t / std::sqrt(9 + 12 * t * t);
  Voigt sigma0(4), rate(4), s;
  sigma0 << -100, -100, -100, 0;
  rate << eta_ps / 2, eta_ps / 2, 0, std::sqrt(1 - eta_ps * eta_ps / 3);
  std::vector<double> state(ElastoPlastic::state_size, 0.0), next(state);
  VoigtMatrix D;
  for (int step = 1; step <= 200; ++step) {
    m.update(5e-4 * step * rate, sigma0, state.data(), s, D, next.data());
    state = next;
  }
  ASSERT_EQ(state[ElastoPlastic::plastic_flag_slot], 1.0);
  const Voigt st = s + sigma0;
  const double centre = 0.5 * (st(0) + st(1));
  const double radius = std::sqrt(0.25 * (st(0) - st(1)) * (st(0) - st(1)) + st(3) * st(3));
  EXPECT_NEAR(2 * radius + 2 * centre * 0.5, 2 * c * std::cos(M_PI / 6), 1e-8 * 100);
}

TEST(DruckerPrager, MatchIsOneOfThree) {
  ParameterSet p;
  p.set("youngs_modulus", E);
  p.set("poissons_ratio", nu);
  p.set("cohesion", c);
  p.set("friction_angle", phi);
  p.set("dilatancy_angle", 40.0);
  p.set("match", std::string("plane_stress"));
  try {
    builtin_materials().create("drucker_prager", p);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("drucker_prager.match: value \"plane_stress\" is not one of: compression, "
                       "extension, plane_strain"),
              std::string::npos)
        << msg;
  }
  p.set("match", std::string("plane_strain"));
  try {
    builtin_materials().create("drucker_prager", p);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("drucker_prager.dilatancy_angle: value 40 deg exceeds "
                                         "friction_angle 30 deg"),
              std::string::npos)
        << e.what();
  }
}

} // namespace
} // namespace bipot
