// Rigid obstacles in the stage driver (StaticAnalysis::Impl): their translation, ramped over
// a stage like a boundary condition, is data of the interface pairs (a body bonded to the
// obstacle included: its tie law holds the jumps).
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

} // namespace bipot
