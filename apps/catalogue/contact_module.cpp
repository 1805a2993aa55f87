#include "apps/catalogue/contact_module.hpp"

#include "contact/solver/interface_assembler.hpp"
#include "contact/solver/interface_newton_system.hpp"
#include "contact/solver/tied_interface.hpp"
#include "fem/analysis/model.hpp"
#include "fem/core/error.hpp"

namespace bipot {

namespace {

class ContactModule final : public InterfaceModule {
public:
  EnforcedInterfaces enforce(const Model& model, const DofMap& dofs,
                             const DofDistribution& dist) const override {
    EnforcedInterfaces out;
    std::vector<contact::InterfaceAssembler*> acting;
    for (std::size_t k = 0; k < model.interfaces.size(); ++k) {
      const contact::Interface& iface = model.interfaces[k];
      if (contact::shares_nodes(iface)) {
        // Its forces, for output: a body bonded to an obstacle is held by it; two bodies
        // named by region pass on what body 1's cells do not balance. (Bodies given by facet
        // sets have no body-1 region to take it from.)
        const TransmittedForce source = iface.obstacle ? TransmittedForce::FromHeldNodes
                                        : model.spec.interfaces[k].between.size() == 2
                                            ? TransmittedForce::FromBody1
                                            : TransmittedForce::None;
        out.interfaces.push_back(std::make_unique<contact::TiedInterface>(iface, dofs, source));
        continue;
      }
      std::vector<contact::StageLaw> stage_laws;
      for (const auto& sl : model.stage_laws)
        if (sl.interface == k) stage_laws.push_back({sl.stage, sl.law.get()});
      auto assembler = std::make_unique<contact::InterfaceAssembler>(
          iface, *model.interface_laws[k], dofs, dist, model.contact_solver, stage_laws);
      acting.push_back(assembler.get());
      out.interfaces.push_back(std::move(assembler));
    }
    if (!acting.empty() && model.contact_solver.exact_newton()) {
      auto system = std::make_unique<contact::InterfaceNewtonSystem>(acting, dofs);
      // Refused at `check` already (apps/common/checked_model.cpp); a model built otherwise
      // gets the same message here.
      const std::string too_large = contact::condensed_size_problem(
          {system->num_dofs(), system->num_multipliers()}, model.spec.contact_solver.where);
      if (!too_large.empty()) throw InputError({too_large});
      out.condensed = std::move(system);
    }
    return out;
  }
};

} // namespace

std::shared_ptr<const InterfaceModule> contact_module() {
  static const auto module = std::make_shared<const ContactModule>();
  return module;
}

} // namespace bipot
