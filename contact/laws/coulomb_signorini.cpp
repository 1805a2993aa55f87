#include "contact/laws/coulomb_signorini.hpp"

#include "fem/core/error.hpp"

namespace bipot::contact {

ParamSchema CoulombSignorini::schema() {
  ParamSchema s("coulomb_signorini",
                "unilateral (Signorini) contact with Coulomb friction, no adhesion");
  s.real("friction_coefficient", "", "Coulomb friction coefficient mu (0 = frictionless)")
      .non_negative()
      .with_default(0.0);
  return s;
}

CoulombSignorini::CoulombSignorini(const ParameterSet& params)
    : CoulombSignorini(params.real("friction_coefficient")) {}

CoulombSignorini::CoulombSignorini(double friction_coefficient) : mu_(friction_coefficient) {
  const auto problem = schema().find("friction_coefficient")->check(mu_);
  if (problem) throw InputError("coulomb_signorini.friction_coefficient: " + *problem);
}

} // namespace bipot::contact
