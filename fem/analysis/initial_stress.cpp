#include "fem/analysis/initial_stress.hpp"

#include <algorithm>

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

} // namespace bipot
