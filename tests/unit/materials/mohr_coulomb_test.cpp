#include "materials/linear_elastic.hpp"
#include "materials/material_registry.hpp"
#include "materials/mohr_coulomb.hpp"
#include "point_driver.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

namespace bipot {
namespace {

using test::cramer;
using test::expect_fd_tangent;
using test::expect_return;

// E = 2.5e4 kPa, ν = 0.25: λ = G = 1e4 kPa, so the principal elasticity is
// C = 1e4 (1⊗1 + 2 I). c = 10 kPa, φ = 30° (sin φ = 1/2, 2c cos φ = 10√3), sin ψ = 0.2.
// Plane normals n and flow vectors m (tension positive, σ1 ≥ σ2 ≥ σ3):
//   main (σ1,σ3): n1 = (1.5, 0, −0.5), m1 = (1.2, 0, −0.8), C m1 = 1e4 (2.8, 0.4, −1.2)
//   (σ2,σ3):      n2 = (0, 1.5, −0.5), m2 = (0, 1.2, −0.8), C m2 = 1e4 (0.4, 2.8, −1.2)
//   (σ1,σ2):      n3 = (1.5, −0.5, 0), m3 = (1.2, −0.8, 0), C m3 = 1e4 (2.8, −1.2, 0.4)
//   cut-off σ1:   t = m = (1, 0, 0),                       C t  = 1e4 (3, 1, 1)
constexpr double E = 2.5e4, nu = 0.25, c = 10.0, phi = 30.0;
const double psi = std::asin(0.2) * 180.0 / M_PI;
const double k = 10.0 * std::sqrt(3.0); // 2 c cos φ
const Vec3 Cm1 = 1e4 * Vec3(2.8, 0.4, -1.2), Cm2 = 1e4 * Vec3(0.4, 2.8, -1.2),
           Cm3 = 1e4 * Vec3(2.8, -1.2, 0.4), Ct = 1e4 * Vec3(3, 1, 1);
double f1(const Vec3& s) {
  return 1.5 * s(0) - 0.5 * s(2) - k;
}
double f2(const Vec3& s) {
  return 1.5 * s(1) - 0.5 * s(2) - k;
}
double f3(const Vec3& s) {
  return 1.5 * s(0) - 0.5 * s(1) - k;
}

// Trial (−20, −50, −150): f1 = −30 + 75 − 10√3 > 0, n1·C m1 = 1e4 (4.2 + 0.6) = 4.8e4, so
// Δλ = f1/4.8e4 and σ = σ* − Δλ C m1 ≈ (−36.15, −52.31, −143.08), still ordered.
TEST(MohrCoulomb, PlaneReturn) {
  MohrCoulomb m({E, nu, c, phi, psi});
  const Vec3 t(-20, -50, -150);
  const double dl = f1(t) / 4.8e4;
  expect_return(m, t, t - dl * Cm1, MohrCoulomb::Plane);
}

// Trial (−20, −25, −150): the plane return would give σ1 < σ2. Left edge (σ1 = σ2): planes 1
// and 2, M = 1e4 [[4.8, 1.2], [1.2, 4.8]] (n1·C m2 = 1.5·0.4 + 0.5·1.2 = 1.2), rhs (f1, f2).
TEST(MohrCoulomb, LeftEdgeReturn) {
  MohrCoulomb m({E, nu, c, phi, psi});
  const Vec3 t(-20, -25, -150);
  const auto [a, b] = cramer(4.8e4, 1.2e4, 1.2e4, 4.8e4, f1(t), f2(t));
  const Vec3 s = t - a * Cm1 - b * Cm2;
  EXPECT_NEAR(s(0), s(1), 1e-12 * 150);
  expect_return(m, t, s, MohrCoulomb::EdgeLeft);
}

// Trial (−20, −148, −150): the plane return would give σ2 < σ3. Right edge (σ2 = σ3): planes
// 1 and 3, M = 1e4 [[4.8, 4.0], [4.0, 4.8]] (n1·C m3 = 4.2 − 0.2, n3·C m1 = 4.2 − 0.2).
TEST(MohrCoulomb, RightEdgeReturn) {
  MohrCoulomb m({E, nu, c, phi, psi});
  const Vec3 t(-20, -148, -150);
  const auto [a, b] = cramer(4.8e4, 4.0e4, 4.0e4, 4.8e4, f1(t), f3(t));
  const Vec3 s = t - a * Cm1 - b * Cm3;
  EXPECT_NEAR(s(1), s(2), 1e-12 * 150);
  expect_return(m, t, s, MohrCoulomb::EdgeRight);
}

// Trial (40, 35, 30) lies beyond the apex c cot φ = 10√3: σ = 10√3 (1, 1, 1), with and
// without dilatancy (ψ = 0: no flow changes the mean stress, the apex is the return).
TEST(MohrCoulomb, ApexReturn) {
  const Vec3 t(40, 35, 30), apex = Vec3::Constant(10 * std::sqrt(3.0));
  expect_return(MohrCoulomb({E, nu, c, phi, psi}), t, apex, MohrCoulomb::Apex);
  expect_return(MohrCoulomb({E, nu, c, phi, 0.0}), t, apex, MohrCoulomb::Apex);
}

// Cut-off σt = 5. Trial (8, 2, 1): inside Mohr–Coulomb (12 − 0.5 − 10√3 < 0), σ1 > σt:
// Δλ = 3/3e4, σ = (8, 2, 1) − 1e-4 · 1e4 (3, 1, 1) = (5, 1, 0).
// Trial (8, 7, 1): the plane would give σ2 > σ1; cut-off edge, M = 1e4 [[3, 1], [1, 3]],
// rhs (3, 2): Δλ = (7/8, 3/8) 1e-4, σ = (5, 5, −0.25).
TEST(MohrCoulomb, TensionCutoffPlaneAndEdge) {
  MohrCoulomb m({E, nu, c, phi, psi, 5.0});
  expect_return(m, Vec3(8, 2, 1), Vec3(5, 1, 0), MohrCoulomb::Tension);
  expect_return(m, Vec3(8, 7, 1), Vec3(5, 5, -0.25), MohrCoulomb::TensionEdge);
}

// Cut-off σt = 2, trial (20, −20, −30): the plane return leaves σ1 ≈ 3.85 > σt and the
// cut-off alone leaves f1 > 0: corner of the main plane and the cut-off,
// M = 1e4 [[n1·C m1, n1·C t], [t·C m1, t·C t]] = 1e4 [[4.8, 4.0], [2.8, 3]], rhs (f1, 18).
TEST(MohrCoulomb, TensionCutoffCorner) {
  MohrCoulomb m({E, nu, c, phi, psi, 2.0});
  const Vec3 t(20, -20, -30);
  const auto [a, b] = cramer(4.8e4, 4.0e4, 2.8e4, 3.0e4, f1(t), t(0) - 2.0);
  const Vec3 s = t - a * Cm1 - b * Ct;
  EXPECT_NEAR(s(0), 2.0, 1e-12 * 30);
  expect_return(m, t, s, MohrCoulomb::PlaneTension);
}

// Cut-off σt = 5 below the apex 10√3, trial (10, 9, 8): every cut-off plane active,
// M = C, so Δλ = C⁻¹ (5, 4, 3) and σ = (5, 5, 5).
TEST(MohrCoulomb, TensionCutoffApex) {
  MohrCoulomb m({E, nu, c, phi, psi, 5.0});
  expect_return(m, Vec3(10, 9, 8), Vec3::Constant(5.0), MohrCoulomb::TensionApex);
}

// Cut-off σt = 3, trial (12.9, 12.9, −33): the return ends where four planes meet,
// σ1 = σ2 = σt on the yield surface: 1.5·3 − 0.5 σ3 = k gives σ = (3, 3, 9 − 2k); the
// flow is a non-negative combination of four vectors, found through a 3-plane subset.
// Found by a randomized search over trial stresses, which failed before those subsets.
TEST(MohrCoulomb, TensionCutoffEdgeOnTheYieldSurface) {
  MohrCoulomb m({E, nu, c, phi, psi, 3.0});
  expect_return(m, Vec3(12.9, 12.9, -33), Vec3(3, 3, 9 - 2 * k), MohrCoulomb::PlaneTensionEdge);
}

// Cut-off σt = 3, trial (40, −30, −31): σ1 = σt and σ2 = σ3 on the main plane,
// 1.5·3 − 0.5 σ3 = k: σ = (3, 9 − 2k, 9 − 2k).
TEST(MohrCoulomb, RightEdgeWithTensionCutoff) {
  MohrCoulomb m({E, nu, c, phi, psi, 3.0});
  expect_return(m, Vec3(40, -30, -31), Vec3(3, 9 - 2 * k, 9 - 2 * k),
                MohrCoulomb::EdgeRightTension);
}

TEST(MohrCoulomb, ConsistentTangentInEveryBranch) {
  MohrCoulomb m({E, nu, c, phi, psi}), cut({E, nu, c, phi, psi, 5.0}),
      corner({E, nu, c, phi, psi, 2.0});
  expect_fd_tangent(m, Vec3(-20, -50, -150), MohrCoulomb::Plane);
  expect_fd_tangent(m, Vec3(-20, -25, -150), MohrCoulomb::EdgeLeft);
  expect_fd_tangent(m, Vec3(-20, -148, -150), MohrCoulomb::EdgeRight);
  expect_fd_tangent(m, Vec3(40, 35, 30), MohrCoulomb::Apex);
  expect_fd_tangent(cut, Vec3(8, 2, 1), MohrCoulomb::Tension);
  expect_fd_tangent(cut, Vec3(8, 7, 1), MohrCoulomb::TensionEdge);
  expect_fd_tangent(corner, Vec3(20, -20, -30), MohrCoulomb::PlaneTension);
  expect_fd_tangent(cut, Vec3(10, 9, 8), MohrCoulomb::TensionApex);
  const MohrCoulomb cut3({E, nu, c, phi, psi, 3.0});
  expect_fd_tangent(cut3, Vec3(12.9, 12.5, -33), MohrCoulomb::PlaneTensionEdge);
  expect_fd_tangent(cut3, Vec3(40, -30, -31), MohrCoulomb::EdgeRightTension);
  expect_fd_tangent(m, Vec3(-60, -80, -100), MohrCoulomb::Elastic);
}

// The apex tangent is zero, exactly, and that is the consistent tangent: mohr_coulomb is
// perfectly plastic, so every trial beyond the apex returns to the same stress c cot phi
// (10 sqrt 3 here) and dsigma/deps = 0 (the finite differences of ConsistentTangentInEveryBranch
// agree). For these trials the three-plane set has a negative multiplier (at (40, 35, 30):
// -2.28e-3 on the main plane), so the return is the vertex itself. A hardening apex would
// move with the flow and have a tangent, but no material here has one. How Newton copes with
// the zero rows: docs/materials/mohr_coulomb.md.
TEST(MohrCoulomb, ApexTangentIsExactlyZero) {
  const MohrCoulomb m({E, nu, c, phi, psi});
  const double apex = 10 * std::sqrt(3.0), scale = m.elasticity_matrix(6).cwiseAbs().maxCoeff();
  for (const Vec3& t : {Vec3(40, 35, 30), Vec3(20, 18, 17.5), Vec3(300, 100, 90)}) {
    Voigt strain = Voigt::Zero(6), s, sigma0(6);
    sigma0 << t(0), t(1), t(2), 0, 0, 0;
    VoigtMatrix D;
    m.update(strain, sigma0, nullptr, s, D, nullptr);
    EXPECT_EQ(m.return_stress(stress_tensor(sigma0), 0.0).branch, MohrCoulomb::Apex);
    EXPECT_NEAR((s + sigma0)(0), apex, 1e-12 * apex);
    EXPECT_NEAR((s + sigma0)(2), apex, 1e-12 * apex);
    EXPECT_LE(D.cwiseAbs().maxCoeff(), 1e-12 * scale);
    const VoigtMatrix fd = test::fd_tangent(m, strain, sigma0, nullptr, 1e-7);
    EXPECT_LE(fd.cwiseAbs().maxCoeff(), 1e-6 * scale);
  }
}

// Exactly equal trial principal stresses (σxx = σyy, as in a triaxial test): the tangent's
// rotation term uses its limit ∂s_a/∂λ_a − ∂s_a/∂λ_b there; central differences (whose
// perturbations split the pair) must agree. Left edge (σ1 = σ2) and right edge (σ2 = σ3).
TEST(MohrCoulomb, TangentAtEqualTrialPrincipalStresses) {
  MohrCoulomb m({E, nu, c, phi, psi});
  for (const Vec3& t : {Vec3(-20, -20, -150), Vec3(-20, -150, -150)}) {
    Voigt sigma0(6), strain(6), s;
    sigma0 << t(0), t(1), t(2), 0, 0, 0;
    strain << 1e-5, 1e-5, 1e-5, 0, 0, 0; // keeps the pair equal
    VoigtMatrix D;
    m.update(strain, sigma0, nullptr, s, D, nullptr);
    const VoigtMatrix fd = test::fd_tangent(m, strain, sigma0, nullptr, 1e-9);
    EXPECT_LT(test::relative_difference(D, fd, m.elasticity_matrix(6)), 1e-6) << D << "\n\n" << fd;
  }
}

// Issue 12: the Mohr-Coulomb pile (rccm_mohr_coulomb.yaml: c = 5 kPa, phi = 34.8 deg,
// psi = 5 deg) stalls at tolerance 1e-8 while one surface soil point switches between the
// left edge (sigma1 = hoop = sigma2) and the main plane from one outer iteration to the next.
// Its state there (axisymmetric strain [rr, zz, hoop, rz], geostatic sigma0 and plastic
// strain, from a trace of the stalled increment) and the strain direction of the Newton
// step, along which the return switches EdgeLeft -> Plane. A stress jump there the size of
// the stalled residual (2.6e-3 kN at a node) would be of order 1e-2 kPa (estimated from the
// cell size); the return is Lipschitz down to strain steps of 1e-13 (below, the 1e-10
// relative admissibility tolerance shows: ~4e-10 kPa). The stall is not a discontinuity
// (docs/performance_plasticity.md).
TEST(MohrCoulomb, ContinuousWhereThePileStalled) {
  const MohrCoulomb m({3.0e4, 0.33, 5.0, 34.8, 5.0});
  Voigt eps0(4), dir(4), sigma0(4);
  eps0 << -1.4626806408e-03, -3.2457062046e-04, 2.3121322861e-03, -2.6691470588e-03;
  dir << -1.4476814452e-06, -2.1418127694e-05, 3.9350395347e-06, 1.3909474674e-04;
  sigma0 << -0.645, -1.5, -0.645, 0.0;
  Voigt plastic(4); // ElastoPlastic's state: plastic strain, then eq. plastic strain 2.69e-3
  plastic << -1.3666958053e-03, -2.4637839454e-04, 2.0370679107e-03, -2.1864753755e-03;
  double state[ElastoPlastic::state_size] = {0, 0, 0, 0, 0, 0, 2.6883995255e-03, 0, 1};
  std::copy(plastic.data(), plastic.data() + 4, state);
  const VoigtMatrix D = m.elasticity_matrix(4);
  const auto branch = [&](const Voigt& e) {
    return m.return_stress(stress_tensor(sigma0 + D * (e - plastic)), 0.0).branch;
  };
  // Bisect for the switch along the Newton step (it is at about 0.0094 of the step).
  double a = 0.0, b = 0.02;
  ASSERT_EQ(branch(eps0), MohrCoulomb::EdgeLeft);
  ASSERT_EQ(branch(eps0 + b * dir), MohrCoulomb::Plane);
  for (int k = 0; k < 60; ++k)
    (branch(eps0 + 0.5 * (a + b) * dir) == MohrCoulomb::EdgeLeft ? a : b) = 0.5 * (a + b);
  const Voigt at = eps0 + a * dir, s = test::stress_at(m, at, sigma0, state);
  // Directions spread over the 4 components; |d sigma| <= 2 max|D| |d eps| + round-off.
  const double bound = 2 * D.cwiseAbs().maxCoeff();
  for (int k = 0; k < 200; ++k) {
    Voigt d(4);
    for (int i = 0; i < 4; ++i)
      d(i) = std::sin(1.7 * k + 2.3 * i + 0.4);
    d.normalize();
    for (double h = 1e-9; h > 0.9e-13; h *= 0.1) {
      const double jump = (test::stress_at(m, at + h * d, sigma0, state) - s).norm();
      EXPECT_LE(jump, bound * h + 1e-9) << "direction " << k << ", step " << h;
    }
  }
}

// return_stress() takes a trial as elastic from closed-form eigenvalues when it lies inside
// by more than 1e-6 of the stresses, and decides nearer the surface on the exact
// decomposition. Trials 1e-9 of the stresses outside must yield, and 1e-9 inside must not,
// in any orientation and with two principal stresses nearly or exactly equal (where the
// closed form is least accurate). The hydrostatic shift t moves every plane's f by exactly t
// (each normal's components sum to 1.5 − 0.5 = 1), which places a trial at a chosen f.
TEST(MohrCoulomb, TrialsJustOutsideYieldAndJustInsideDoNot) {
  MohrCoulomb m({E, nu, c, phi, psi});
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int outside = 0, inside = 0;
  for (int sample = 0; sample < 20000; ++sample) {
    Vec3 s(-200 * u(gen), -200 * u(gen), -200 * u(gen));
    std::sort(s.data(), s.data() + 3, std::greater<double>());
    const double gap = std::pow(10.0, -16 + 14 * u(gen)) * 100;  // 1e-14 to 1 kPa
    if (sample % 3 == 1) s(1) = s(0) - (sample % 2 ? gap : 0.0); // near the left edge
    if (sample % 3 == 2) s(1) = s(2) + (sample % 2 ? gap : 0.0); // near the right edge
    const double f = std::max({f1(s), f2(s), f3(s)});
    const double scale = s.cwiseAbs().maxCoeff() + k;
    const bool out = sample % 2 == 0;
    const Vec3 trial = s + Vec3::Constant((out ? 1e-9 : -1e-9) * scale - f);
    const Mat3 Q = Eigen::Quaterniond(u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5)
                       .normalized()
                       .toRotationMatrix();
    const Mat3 T = Q * trial.asDiagonal() * Q.transpose();
    const int branch = m.return_stress(T, 0.0).branch;
    if (out) {
      EXPECT_NE(branch, 0) << "trial " << trial.transpose() << " is outside by 1e-9";
      ++outside;
    } else {
      EXPECT_EQ(branch, 0) << "trial " << trial.transpose() << " is inside by 1e-9";
      ++inside;
    }
    if (HasFailure()) break;
  }
  EXPECT_EQ(outside + inside, 20000);
}

// With a huge cohesion nothing yields: stress and tangent equal linear_elastic's.
TEST(MohrCoulomb, HugeCohesionEqualsLinearElastic) {
  MohrCoulomb m({E, nu, 1e12, phi, psi});
  LinearElastic el({E, nu});
  for (int n : {4, 6}) {
    Voigt strain(n), sigma0 = Voigt::Zero(n);
    for (int i = 0; i < n; ++i)
      strain(i) = 1e-3 * std::sin(1.0 + i);
    sigma0.head(3) << -30, -40, -50;
    Voigt s1, s2;
    VoigtMatrix D1, D2;
    m.update(strain, sigma0, nullptr, s1, D1, nullptr);
    el.update(strain, sigma0, nullptr, s2, D2, nullptr);
    EXPECT_LE((s1 - s2).cwiseAbs().maxCoeff(), 1e-12 * s2.cwiseAbs().maxCoeff());
    EXPECT_LE((D1 - D2).cwiseAbs().maxCoeff(), 1e-12 * D2.cwiseAbs().maxCoeff());
  }
}

std::string create_error(const std::string& name, ParameterSet p) {
  try {
    builtin_materials().create(name, std::move(p));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MohrCoulomb, BadInputNamesTheKey) {
  ParameterSet p;
  p.set("youngs_modulus", E);
  p.set("poissons_ratio", nu);
  p.set("cohesion", c);
  p.set("friction_angle", phi);
  p.set("dilatancy_angle", 35.0);
  EXPECT_NE(create_error("mohr_coulomb", p)
                .find("mohr_coulomb.dilatancy_angle: value 35 deg exceeds friction_angle 30 deg"),
            std::string::npos)
      << create_error("mohr_coulomb", p);
  p.set("dilatancy_angle", 0.0);
  p.set("friction_angle", 90.0);
  EXPECT_NE(create_error("mohr_coulomb", p)
                .find("mohr_coulomb.friction_angle: value 90 is out of range [0, 90) deg"),
            std::string::npos)
      << create_error("mohr_coulomb", p);
  p.set("friction_angle", -1.0);
  EXPECT_NE(create_error("mohr_coulomb", p)
                .find("mohr_coulomb.friction_angle: value -1 is out of range [0, 90) deg"),
            std::string::npos);
  p.set("friction_angle", 0.0);
  p.set("cohesion", -1.0);
  EXPECT_NE(create_error("mohr_coulomb", p)
                .find("mohr_coulomb.cohesion: value -1 is out of range [0, inf) kPa"),
            std::string::npos)
      << create_error("mohr_coulomb", p);
  p.set("cohesion", 0.0);
  EXPECT_NE(create_error("mohr_coulomb", p)
                .find("mohr_coulomb.cohesion: value 0 with friction_angle 0 leaves the "
                      "mohr_coulomb material no strength"),
            std::string::npos)
      << create_error("mohr_coulomb", p);
  p.set("cohesion", c);
  p.set("tension_cutoff", 3.0);
  EXPECT_EQ(create_error("mohr_coulomb", p), "no error");
}

} // namespace
} // namespace bipot
