// Rigid bodies in the stage driver (StaticAnalysis::Impl): the reference nodes' prescribed
// components are boundary conditions on the master DOFs; forces and moments are loads there.
#include "fem/analysis/detail/static_analysis_impl.hpp"

namespace bipot {

namespace {
const RigidBody& body_named(const Model& model, const std::string& name) {
  for (const RigidBody& b : model.rigid_bodies)
    if (b.name == name) return b;
  throw Error("rigid body '" + name + "' not found"); // checked by build_model
}
} // namespace

void StaticAnalysis::Impl::begin_rigid_body_stage(const StageSpec& stage) {
  for (const auto& c : stage.rigid_body_conditions)
    if (!c.force)
      target[rigid_body_dof(body_named(model, c.body), dofs, model.kinematics, c.component)] =
          c.value;
}

void StaticAnalysis::Impl::add_rigid_body_loads(const StageSpec& stage,
                                                DistributedVector& F) const {
  if (model.rigid_bodies.empty()) return;
  if (dist.rank() == 0) // each load once; finish_assembly() sends it to its owner
    for (const auto& c : stage.rigid_body_conditions)
      if (c.force)
        F.add(rigid_body_dof(body_named(model, c.body), dofs, model.kinematics, c.component),
              c.value);
  rigid.transfer(F); // includes finish_assembly()
}

void StaticAnalysis::Impl::record_rigid_body_forces() {
  if (model.rigid_bodies.empty()) return;
  // What the reference node transmits: f_int there = the reaction (f_int − f_ext) plus the
  // applied load.
  const std::vector<double> load = F_step.gather_all();
  rigid_force_all.assign(reaction_all.size(), 0.0);
  for (const RigidBody& b : model.rigid_bodies)
    for (int k = 0; k < rigid_body_components(model.kinematics); ++k) {
      const Index d = rigid_body_dof(b, dofs, model.kinematics, k);
      rigid_force_all[d] = reaction_all[d] + load[d];
    }
}

} // namespace bipot
