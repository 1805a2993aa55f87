// Rigid obstacles in the stage driver (StaticAnalysis::Impl): their translation, ramped over
// a stage like a boundary condition, is data of the contact pairs; a tied (perfect bonding)
// obstacle holds its nodes by prescribed displacements instead, which is exact.
#include "fem/analysis/detail/static_analysis_impl.hpp"

namespace bipot {

void StaticAnalysis::Impl::begin_obstacle_stage(const StageSpec& stage) {
  obstacle_start.resize(interfaces.size());
  obstacle_target.resize(interfaces.size());
  for (std::size_t k = 0; k < interfaces.size(); ++k) {
    // An obstacle the stage does not name stays where it is (like a gap shift).
    obstacle_start[k] = obstacle_target[k] = interfaces[k]->obstacle_displacement();
    for (const auto& d : stage.obstacle_displacements)
      if (d.interface == interfaces[k]->name())
        for (std::size_t c = 0; c < d.value.size(); ++c)
          obstacle_target[k][c] = d.value[c];
    for (Index node : interfaces[k]->held_nodes())
      for (int c = 0; c < dim; ++c)
        target[dofs.dof(node, c)] = obstacle_target[k][c];
  }
}

void StaticAnalysis::Impl::move_obstacles(double lambda) {
  for (std::size_t k = 0; k < interfaces.size(); ++k) {
    if (!interfaces[k]->has_obstacle()) continue;
    std::array<double, 3> u{0, 0, 0};
    for (int c = 0; c < 3; ++c)
      u[c] = obstacle_start[k][c] + lambda * (obstacle_target[k][c] - obstacle_start[k][c]);
    interfaces[k]->set_obstacle_displacement(u);
  }
}

void StaticAnalysis::Impl::tied_obstacle_forces() {
  for (std::size_t k = 0; k < interfaces.size(); ++k) {
    if (interfaces[k]->transmitted_force() != TransmittedForce::FromHeldNodes) continue;
    // The obstacle is the support of the nodes it holds: the body pushes on it with the
    // opposite of their reactions.
    std::vector<double> force(reaction_all.size(), 0.0);
    for (Index node : interfaces[k]->held_nodes())
      for (int c = 0; c < dim; ++c)
        force[dofs.dof(node, c)] = -reaction_all[dofs.dof(node, c)];
    interfaces[k]->set_transmitted_forces(force);
  }
}

} // namespace bipot
