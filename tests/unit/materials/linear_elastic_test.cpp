#include "materials/linear_elastic.hpp"
#include "materials/material_registry.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>

namespace bipot {
namespace {

// Closed forms are evaluated in double precision from the same formulas, so 1e-12 relative
// leaves only round-off.
constexpr double tol = 1e-12;

TEST(LinearElastic, UniaxialStressGivesYoungsModulusAndPoisson3D) {
  const double E = 3.0e4, nu = 0.33;
  LinearElastic m({E, nu});
  // Strain state of uniaxial stress sigma_xx = s: eps_xx = s/E, eps_yy = eps_zz = -nu s/E.
  const double s = 120.0;
  Voigt eps = Voigt::Zero(6);
  eps << s / E, -nu * s / E, -nu * s / E, 0, 0, 0;
  Voigt sig;
  VoigtMatrix D;
  m.update(eps, Voigt::Zero(eps.size()), nullptr, sig, D, nullptr);
  EXPECT_NEAR(sig(0), s, tol * s);
  for (int i = 1; i < 6; ++i)
    EXPECT_NEAR(sig(i), 0.0, tol * s);
}

TEST(LinearElastic, PureShearGivesShearModulus) {
  const double E = 2.1e8, nu = 0.3, G = E / (2 * (1 + nu));
  LinearElastic m({E, nu});
  for (int n : {4, 6}) {
    Voigt eps = Voigt::Zero(n);
    eps(3) = 1e-3; // engineering shear strain gamma_xy
    Voigt sig;
    VoigtMatrix D;
    m.update(eps, Voigt::Zero(eps.size()), nullptr, sig, D, nullptr);
    EXPECT_NEAR(sig(3), G * 1e-3, tol * G * 1e-3);
    EXPECT_NEAR(sig(0), 0.0, tol * G * 1e-3);
  }
}

TEST(LinearElastic, PlaneStrainOutOfPlaneStressIsNuTimesInPlaneSum) {
  const double E = 1.0e5, nu = 0.25;
  LinearElastic m({E, nu});
  Voigt eps = Voigt::Zero(4);
  eps << 1e-3, -2e-4, 0.0, 0.0;
  Voigt sig;
  VoigtMatrix D;
  m.update(eps, Voigt::Zero(eps.size()), nullptr, sig, D, nullptr);
  // Plane strain: sigma_zz = nu (sigma_xx + sigma_yy).
  EXPECT_NEAR(sig(2), nu * (sig(0) + sig(1)), tol * std::abs(sig(0)));
}

TEST(LinearElastic, BulkModulusUnderHydrostaticStrain) {
  const double E = 5.0e4, nu = 0.2, K = E / (3 * (1 - 2 * nu));
  LinearElastic m({E, nu});
  Voigt eps = Voigt::Zero(6);
  eps << 1e-4, 1e-4, 1e-4, 0, 0, 0;
  Voigt sig;
  VoigtMatrix D;
  m.update(eps, Voigt::Zero(eps.size()), nullptr, sig, D, nullptr);
  // Mean stress = K * volumetric strain.
  EXPECT_NEAR((sig(0) + sig(1) + sig(2)) / 3, K * 3e-4, tol * K * 3e-4);
  // The tangent is symmetric and positive definite.
  EXPECT_TRUE(D.isApprox(D.transpose(), 1e-15));
  const Eigen::MatrixXd Dm = D;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Dm);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
}

TEST(MaterialRegistry, CreatesLinearElasticWithDefaults) {
  ParameterSet p;
  p.set("youngs_modulus", 3.0e6);
  p.set("poissons_ratio", 0.3);
  auto m = builtin_materials().create("linear_elastic", p);
  EXPECT_EQ(m->name(), "linear_elastic");
  EXPECT_EQ(m->unit_weight(), 0.0);
}

TEST(MaterialRegistry, OutOfRangeAndUnknownMessages) {
  ParameterSet p;
  p.set("youngs_modulus", -1.0);
  p.set("poissons_ratio", 0.5);
  p.set("youngs_modulos", 1.0);
  try {
    builtin_materials().create("linear_elastic", p);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("linear_elastic.youngs_modulus: value -1 is out of range (0, inf) kPa"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("linear_elastic.poissons_ratio: value 0.5 is out of range (-1, 0.5)"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("linear_elastic.youngs_modulos: unknown key for 'linear_elastic' (did you "
                       "mean 'youngs_modulus'?)"),
              std::string::npos)
        << msg;
    EXPECT_EQ(e.problems().size(), 3u);
  }
  try {
    builtin_materials().create("linear_elastc", ParameterSet{});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "unknown material 'linear_elastc' (did you mean 'linear_elastic'?); registered: "
                  "drucker_prager, linear_elastic, mohr_coulomb, tresca, von_mises"),
              std::string::npos)
        << e.what();
  }
}

} // namespace
} // namespace bipot
