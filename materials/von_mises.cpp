#include "materials/von_mises.hpp"

#include "materials/linear_elastic.hpp"

#include <cmath>

namespace bipot {

namespace {
Mat3 deviator(const Mat3& s) {
  return s - s.trace() / 3.0 * Mat3::Identity();
}
double equivalent_stress(const Mat3& dev) {
  return std::sqrt(1.5 * dev.cwiseProduct(dev).sum());
}
} // namespace

ParamSchemaOf<VonMises::Parameters> VonMises::schema() {
  using P = Parameters;
  ParamSchemaOf<P> s("von_mises", "von Mises (J2) plasticity with linear isotropic hardening");
  add_hooke_keys(s);
  s.real("yield_stress", &P::yield_stress, "kPa", "initial uniaxial yield stress sigma_y")
      .positive();
  s.real("hardening_modulus", &P::hardening_modulus, "kPa",
         "linear isotropic hardening modulus H: yield stress sigma_y + H * (equivalent plastic "
         "strain)")
      .non_negative()
      .defaulted();
  add_unit_weight_key(s);
  return s;
}

VonMises::VonMises(Checked<Parameters> p)
    : ElastoPlastic(p->youngs_modulus, p->poissons_ratio, p->unit_weight),
      yield_stress_(p->yield_stress), hardening_modulus_(p->hardening_modulus) {}

double VonMises::yield_function(const Mat3& stress, double kappa) const {
  return equivalent_stress(deviator(stress)) - (yield_stress_ + hardening_modulus_ * kappa);
}

ElastoPlastic::Return VonMises::return_stress(const Mat3& trial, double kappa) const {
  Return r;
  const double f = yield_function(trial, kappa);
  if (f <= 0.0) return r;
  const double G = shear_modulus(), H = hardening_modulus_;
  const Mat3 s = deviator(trial);
  const double q = equivalent_stress(s);
  const double dgamma = f / (3 * G + H);
  const double beta = 1.0 - 3 * G * dgamma / q; // s = β s_trial
  r.branch = Radial;
  r.stress = trial - (1.0 - beta) * s;
  r.hardening_increment = dgamma;
  // d(p I + β s) with dq = 3/2 s:ds / q and dΔγ = dq / (3G + H).
  r.jacobian = jacobian_from([&](const Mat3& dA) {
    const Mat3 ds = deviator(dA);
    const double dq = 1.5 * s.cwiseProduct(ds).sum() / q;
    const double dbeta = -3 * G * (dq / (3 * G + H) - dgamma * dq / q) / q;
    return Mat3(dA.trace() / 3.0 * Mat3::Identity() + beta * ds + dbeta * s);
  });
  return r;
}

} // namespace bipot
