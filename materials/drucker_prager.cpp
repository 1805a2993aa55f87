#include "materials/drucker_prager.hpp"

#include "materials/linear_elastic.hpp"
#include "materials/mohr_coulomb.hpp"

#include <cmath>

namespace bipot {

namespace {
constexpr double degree = M_PI / 180.0;

struct Invariants {
  double p; // mean stress
  Mat3 s;   // deviator
  double j; // sqrt(J2)
};
Invariants invariants(const Mat3& stress) {
  Invariants v;
  v.p = stress.trace() / 3.0;
  v.s = stress - v.p * Mat3::Identity();
  v.j = std::sqrt(0.5 * v.s.cwiseProduct(v.s).sum());
  return v;
}
} // namespace

std::pair<double, double> DruckerPrager::cone_constants(double angle_deg, Match match) {
  const double s = std::sin(angle_deg * degree), c = std::cos(angle_deg * degree);
  switch (match) {
  case Match::Compression: // through the MC compression meridian (outer cone)
    return {6 * s / (std::sqrt(3.0) * (3 - s)), 6 * c / (std::sqrt(3.0) * (3 - s))};
  case Match::Extension: // through the extension meridian (inner cone)
    return {6 * s / (std::sqrt(3.0) * (3 + s)), 6 * c / (std::sqrt(3.0) * (3 + s))};
  case Match::PlaneStrain: { // same plane-strain collapse load as MC
    const double t = s / c, d = std::sqrt(9 + 12 * t * t);
    return {3 * t / d, 3 / d};
  }
  }
  return {0.0, 0.0};
}

ParamSchemaOf<DruckerPrager::Parameters> DruckerPrager::schema() {
  ParamSchemaOf<Parameters> s("drucker_prager",
                              "Drucker-Prager plasticity (non-associated, perfectly plastic), "
                              "the cone matched to Mohr-Coulomb");
  add_hooke_keys(s);
  add_friction_keys(s);
  s.choice("match", &Parameters::match,
           {{"compression", Match::Compression},
            {"extension", Match::Extension},
            {"plane_strain", Match::PlaneStrain}},
           "which Mohr-Coulomb condition the cone reproduces: its compression meridian (outer "
           "cone), extension meridian (inner cone) or plane-strain strength")
      .defaulted();
  add_unit_weight_key(s);
  return s;
}

DruckerPrager::DruckerPrager(Checked<Parameters> p)
    : ElastoPlastic(p->youngs_modulus, p->poissons_ratio, p->unit_weight), cohesion_(p->cohesion) {
  const Match match = p->match;
  const double friction_angle = p->friction_angle, dilatancy_angle = p->dilatancy_angle;
  std::tie(eta_, xi_) = cone_constants(friction_angle, match);
  eta_bar_ = cone_constants(dilatancy_angle, match).first;
}

double DruckerPrager::yield_function(const Mat3& stress, double) const {
  const Invariants v = invariants(stress);
  return v.j + eta_ * v.p - xi_ * cohesion_;
}

Mat3 DruckerPrager::project_onto_cone(const Mat3& stress) const {
  const Invariants v = invariants(stress);
  const double f = v.j + eta_ * v.p - xi_ * cohesion_;
  if (f <= 0.0) return stress;
  const double G = shear_modulus(), K = bulk_modulus();
  const double dgamma = f / (G + K * eta_ * eta_); // associated: flow = ∂f/∂σ
  if (v.j - G * dgamma >= 0.0)
    return (v.p - K * eta_ * dgamma) * Mat3::Identity() + (1 - G * dgamma / v.j) * v.s;
  return xi_ * cohesion_ / eta_ * Mat3::Identity(); // apex (η > 0 here: see the header)
}

ElastoPlastic::Return DruckerPrager::return_stress(const Mat3& trial, double) const {
  Return r;
  const Invariants v = invariants(trial);
  const double f = v.j + eta_ * v.p - xi_ * cohesion_;
  if (f <= 0.0) return r;
  const double G = shear_modulus(), K = bulk_modulus();
  // The fixed point of the bipotential projection (header): Δγ on the face, else at the apex.
  double dgamma = f / (G + K * eta_ * eta_bar_);
  r.branch = v.j - G * dgamma >= 0.0 ? Cone : Apex;
  if (r.branch == Apex) dgamma = v.j / G;
  r.stress = project_onto_cone(trial + K * (eta_ - eta_bar_) * dgamma * Mat3::Identity());
  if (r.branch == Apex) {
    r.jacobian.setZero(); // the apex stress does not depend on the trial
    return r;
  }
  const double H = G + K * eta_ * eta_bar_;
  r.jacobian = jacobian_from([&](const Mat3& dA) {
    const double dp = dA.trace() / 3.0;
    const Mat3 ds = dA - dp * Mat3::Identity();
    const double dj = v.s.cwiseProduct(ds).sum() / (2 * v.j);
    const double ddgamma = (dj + eta_ * dp) / H;
    return Mat3((dp - K * eta_bar_ * ddgamma) * Mat3::Identity() + (1 - G * dgamma / v.j) * ds -
                G * (ddgamma / v.j - dgamma * dj / (v.j * v.j)) * v.s);
  });
  return r;
}

} // namespace bipot
