#pragma once
// RCCM without its exact springs' integral (InterfaceLaw::spring_work): the energy ledger then
// integrates the springs' work by its three-point rule and the trapezoid, as it does for a
// viscous law or a project's law that gives no such integral. The tests of the rule and of the
// step control on the balance (`energy_tolerance`) use it on rate-independent runs, whose
// closed forms they know, registered in a catalogue as `rccm_by_rule`:
//   catalogue.interface_laws.add<test::RccmByRule>();
#include "contact/laws/rccm.hpp"

#include <optional>
#include <string>
#include <utility>

namespace bipot::test {

class RccmByRule : public contact::Rccm {
public:
  static ParamSchemaOf<Parameters> schema() {
    ParamSchemaOf<Parameters> s = Rccm::schema();
    s.rename("rccm_by_rule", "RCCM, its springs' work left to the energy ledger's quadrature");
    return s;
  }
  explicit RccmByRule(const Parameters& p) : Rccm(p) {}
  explicit RccmByRule(Checked<Parameters> p) : Rccm(std::move(p)) {}
  std::string name() const override { return "rccm_by_rule"; }
  std::optional<double> spring_work(double, const LocalVector&, const LocalVector&) const override {
    return std::nullopt;
  }
};

} // namespace bipot::test
