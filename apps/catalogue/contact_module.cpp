#include "apps/catalogue/contact_module.hpp"

#include "contact/interface/interface_mesh.hpp"
#include "contact/solver/contact_solver_options.hpp"
#include "contact/solver/interface_assembler.hpp"
#include "contact/solver/interface_newton_system.hpp"
#include "contact/solver/tied_interface.hpp"
#include "fem/core/error.hpp"

#include <algorithm>

namespace bipot {

namespace {

// What the contact module keeps of a model: the laws (owned) and the full solver options.
struct ContactData final : InterfaceData {
  std::vector<std::unique_ptr<contact::InterfaceLaw>> laws; ///< one per interface
  /// A law a stage puts in force on an interface (stage `interfaces:`), in stage order.
  struct StageLaw {
    std::size_t stage = 0, interface = 0;
    std::unique_ptr<contact::InterfaceLaw> law;
  };
  std::vector<StageLaw> stage_laws;
  contact::ContactSolverOptions options;
};

const ContactData& data_of(const Model& model) {
  const auto* data = dynamic_cast<const ContactData*>(model.interface_data.get());
  if (!data) throw Error("the model's interfaces were not built by the contact module");
  return *data;
}

contact::RigidObstacle obstacle_of(const ObstacleSpec& spec) {
  using Shape = contact::RigidObstacle::Shape;
  contact::RigidObstacle o;
  o.shape = spec.type == "circle"     ? Shape::Circle
            : spec.type == "sphere"   ? Shape::Sphere
            : spec.type == "cylinder" ? Shape::Cylinder
                                      : Shape::Plane;
  const std::vector<double>& direction = o.shape == Shape::Cylinder ? spec.axis : spec.normal;
  for (std::size_t i = 0; i < 3; ++i) {
    o.point[i] = i < spec.point.size() ? spec.point[i] : 0.0;
    o.direction[i] = i < direction.size() ? direction[i] : 0.0;
  }
  o.radius = spec.radius;
  return o;
}

// Splits the mesh along every interface: those tied in every stage (perfect bonding) keep
// their shared nodes, the others get the body-2 side's nodes duplicated and paired.
void split_interfaces(Model& model, const Registry<contact::InterfaceLaw>& laws,
                      ContactData& data) {
  std::vector<contact::InterfaceDefinition> tied, split;
  std::vector<bool> is_tied;
  const auto& stages = model.spec.stages;
  for (std::size_t s = 0; s < stages.size(); ++s)
    for (const auto& change : stages[s].interface_laws) {
      const auto k = static_cast<std::size_t>(
          std::find_if(model.spec.interfaces.begin(), model.spec.interfaces.end(),
                       [&](const InterfaceSpec& f) { return f.name == change.interface; }) -
          model.spec.interfaces.begin());
      data.stage_laws.push_back({s, k, laws.create_validated(change.law, change.parameters)});
    }
  for (std::size_t k = 0; k < model.spec.interfaces.size(); ++k) {
    const InterfaceSpec& spec = model.spec.interfaces[k];
    data.laws.push_back(laws.create_validated(spec.law, spec.parameters));
    contact::InterfaceDefinition def;
    def.name = spec.name;
    if (spec.between.size() == 2) {
      def.region_a = spec.between[0];
      def.region_b = spec.between[1];
    } else if (spec.facet_sets.size() == 2) {
      def.facet_set_a = spec.facet_sets[0];
      def.facet_set_b = spec.facet_sets[1];
    } else if (spec.facet_sets.size() == 1) { // against an obstacle
      def.facet_set_a = spec.facet_sets[0];
    }
    def.initial_gap = spec.initial_gap;
    if (spec.pairing == "normal") def.pairing = contact::Pairing::Normal;
    if (spec.obstacle) def.obstacle = obstacle_of(*spec.obstacle);
    def.where = spec.where;
    bool tied_always = data.laws.back()->is_tied();
    for (const auto& sl : data.stage_laws)
      if (sl.interface == k) tied_always = tied_always && sl.law->is_tied();
    is_tied.push_back(tied_always);
    (is_tied.back() ? tied : split).push_back(def);
  }
  auto tied_ifaces = contact::split_interfaces(model.mesh, model.kinematics, tied, true);
  auto split_ifaces = contact::split_interfaces(model.mesh, model.kinematics, split, false);
  std::size_t it = 0, is = 0;
  for (bool t : is_tied)
    model.interfaces.push_back(std::move(t ? tied_ifaces[it++] : split_ifaces[is++]));
}

class ContactModule final : public InterfaceModule {
public:
  explicit ContactModule(Registry<contact::InterfaceLaw> laws) : laws_(std::move(laws)) {}

  void build(Model& model) const override {
    auto data = std::make_shared<ContactData>();
    split_interfaces(model, laws_, *data);
    data->options = *contact::contact_solvers().create_validated(
        model.spec.contact_solver.type, model.spec.contact_solver.parameters);
    model.contact_solver = data->options;
    model.interface_data = std::move(data);
  }

  std::vector<std::string> check(const Model& model) const override {
    // generalized_newton's dense condensed system: refused at `check` when too large, rather
    // than once `run` has built the analysis.
    if (!model.contact_solver.exact_newton()) return {};
    std::vector<const contact::Interface*> condensed;
    for (const auto& iface : model.interfaces)
      if (!shares_nodes(iface)) condensed.push_back(&iface);
    const std::string too_large = contact::condensed_size_problem(
        contact::condensed_size(condensed, spatial_dim(model.kinematics)),
        model.spec.contact_solver.where);
    if (too_large.empty()) return {};
    return {too_large};
  }

  std::vector<Index> held_nodes(const Model& model) const override {
    std::vector<Index> held;
    for (std::size_t k = 0; k < model.interfaces.size(); ++k)
      if (model.interfaces[k].obstacle && data_of(model).laws[k]->is_tied())
        for (const auto& p : model.interfaces[k].pairs)
          held.push_back(p.node_a);
    return held;
  }

  EnforcedInterfaces enforce(const Model& model, const DofMap& dofs,
                             const DofDistribution& dist) const override {
    EnforcedInterfaces out;
    if (model.interfaces.empty()) return out;
    const ContactData& data = data_of(model);
    std::vector<contact::InterfaceAssembler*> acting;
    for (std::size_t k = 0; k < model.interfaces.size(); ++k) {
      const contact::Interface& iface = model.interfaces[k];
      if (shares_nodes(iface)) {
        // Its forces, for output: two bodies named by region pass on what body 1's cells do
        // not balance. (Bodies given by facet sets have no body-1 region to take it from.)
        const TransmittedForce source = model.spec.interfaces[k].between.size() == 2
                                            ? TransmittedForce::FromBody1
                                            : TransmittedForce::None;
        out.interfaces.push_back(std::make_unique<contact::TiedInterface>(iface, dofs, source));
        continue;
      }
      std::vector<contact::StageLaw> stage_laws;
      for (const auto& sl : data.stage_laws)
        if (sl.interface == k) stage_laws.push_back({sl.stage, sl.law.get()});
      auto assembler = std::make_unique<contact::InterfaceAssembler>(
          iface, *data.laws[k], dofs, dist, data.options, stage_laws);
      acting.push_back(assembler.get());
      out.interfaces.push_back(std::move(assembler));
    }
    if (!acting.empty() && data.options.exact_newton()) {
      auto system = std::make_unique<contact::InterfaceNewtonSystem>(acting, dofs);
      // Refused at `check` already (check()); a model built otherwise gets the same message.
      const std::string too_large = contact::condensed_size_problem(
          {system->num_dofs(), system->num_multipliers()}, model.spec.contact_solver.where);
      if (!too_large.empty()) throw InputError({too_large});
      out.condensed = std::move(system);
    }
    return out;
  }

private:
  Registry<contact::InterfaceLaw> laws_;
};

} // namespace

std::shared_ptr<const InterfaceModule> contact_module(Registry<contact::InterfaceLaw> laws) {
  return std::make_shared<const ContactModule>(std::move(laws));
}

const contact::InterfaceLaw& interface_law(const Model& model, std::size_t k) {
  return *data_of(model).laws.at(k);
}

} // namespace bipot
