#include "fem/analysis/initial_stress.hpp"

#include "fem/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace bipot {

std::function<Voigt(const std::array<double, 3>&, int)>
initial_stress_function(const Model& model) {
  const int dim = spatial_dim(model.kinematics);
  std::vector<InitialStressSpec> by_region(model.mesh.regions.size() + 1);
  std::vector<bool> has(by_region.size(), false);
  for (const auto& s : model.spec.initial_stress) {
    const int id = model.mesh.regions.at(s.region);
    if (id >= static_cast<int>(by_region.size())) {
      by_region.resize(id + 1);
      has.resize(id + 1, false);
    }
    by_region[id] = s;
    has[id] = true;
  }
  return [dim, by_region, has](const std::array<double, 3>& x, int region) {
    const int nv = voigt_size(dim);
    Voigt sigma = Voigt::Zero(nv);
    if (region < 0 || region >= static_cast<int>(has.size()) || !has[region]) return sigma;
    const InitialStressSpec& s = by_region[region];
    if (s.type == "constant") {
      for (int i = 0; i < nv; ++i)
        sigma(i) = s.stress[i];
      return sigma;
    }
    const int vertical = dim - 1;
    const double depth = std::max(0.0, s.surface - x[vertical]);
    const double sv = -s.unit_weight * depth;
    const double sh = s.lateral_coefficient * sv;
    for (int i = 0; i < 3; ++i)
      sigma(i) = (i == vertical) ? sv : sh;
    return sigma;
  };
}

void check_initial_stress_admissible(const Model& model) {
  if (model.spec.initial_stress.empty()) return;
  const auto sigma0 = initial_stress_function(model);
  std::vector<std::string> problems;
  for (const auto& entry : model.spec.initial_stress) {
    const int region = model.mesh.regions.at(entry.region);
    // Only the plastic materials have a yield surface; the elastic ones accept any stress.
    const Material* material = region < static_cast<int>(model.material_of_region.size())
                                   ? model.material_of_region[region]
                                   : nullptr;
    if (!material) continue;
    std::vector<bool> seen(model.mesh.num_nodes(), false);
    double worst = -INFINITY;
    Index worst_node = -1;
    bool has_yield_surface = true;
    for (Index c = 0; c < model.mesh.num_cells() && has_yield_surface; ++c) {
      if (model.mesh.cell_regions[c] != region) continue;
      for (int a = 0; a < model.mesh.cell_num_nodes(c); ++a) {
        const Index n = model.mesh.cell(c)[a];
        if (seen[n]) continue;
        seen[n] = true;
        const std::optional<double> f =
            material->initial_yield_value(sigma0(model.mesh.nodes[n], region));
        if (!f) { // no yield surface: any stress is admissible
          has_yield_surface = false;
          break;
        }
        if (*f > worst) worst = *f, worst_node = n;
      }
    }
    if (worst_node < 0) continue;
    const Voigt s = sigma0(model.mesh.nodes[worst_node], region);
    // Round-off of the stress components (geostatic: zero at the surface, where a
    // cohesionless material is exactly on its apex).
    if (!(worst > 1e-9 * std::max(1.0, s.norm()))) continue;
    std::ostringstream msg;
    msg << entry.where << ": the initial stress of region '" << entry.region
        << "' lies outside the yield surface of its material '" << material->name() << "': at node "
        << worst_node << " (";
    const int dim = model.mesh.dim;
    for (int i = 0; i < dim; ++i)
      msg << (i ? ", " : "") << model.mesh.nodes[worst_node][i];
    msg << ") the yield function is " << worst << " kPa > 0, stress [";
    for (int i = 0; i < s.size(); ++i)
      msg << (i ? ", " : "") << s(i);
    msg << "] kPa. Lower the stress (K0 nearer 1, a smaller unit weight) or raise the strength";
    problems.push_back(msg.str());
  }
  if (!problems.empty()) throw InputError(problems);
}

} // namespace bipot
