#include "contact/laws/coulomb_signorini.hpp"

namespace bipot::contact {

ParamSchemaOf<CoulombSignorini::Parameters> CoulombSignorini::schema() {
  ParamSchemaOf<Parameters> s("coulomb_signorini",
                              "unilateral (Signorini) contact with Coulomb friction, no adhesion");
  s.real("friction_coefficient", &Parameters::friction_coefficient, "",
         "Coulomb friction coefficient mu (0 = frictionless)")
      .non_negative()
      .defaulted();
  return s;
}

} // namespace bipot::contact
