#include "fem/assembly/load_assembler.hpp"

#include "fem/core/error.hpp"
#include "fem/element/element_values.hpp"
#include "fem/element/facet_values.hpp"
#include "fem/linalg/distributed_vector.hpp"

#include <map>
#include <memory>

namespace bipot {

LoadAssembler::LoadAssembler(const Mesh& mesh, Kinematics kin, const DofMap& dofs,
                             std::vector<bool> cell_owned)
    : mesh_(mesh), kin_(kin), dofs_(dofs), cell_owned_(std::move(cell_owned)) {}

void LoadAssembler::add_pressure(const std::string& facet_set, double pressure,
                                 DistributedVector& f) const {
  add_facet_load(facet_set, f, true, pressure, {});
}

void LoadAssembler::add_traction(const std::string& facet_set, const std::vector<double>& traction,
                                 DistributedVector& f) const {
  add_facet_load(facet_set, f, false, 0.0, traction);
}

void LoadAssembler::add_facet_load(const std::string& facet_set, DistributedVector& f,
                                   bool is_pressure, double pressure,
                                   const std::vector<double>& traction) const {
  auto it = mesh_.facet_sets.find(facet_set);
  if (it == mesh_.facet_sets.end()) throw InputError("no facet set named '" + facet_set + "'");
  const int dim = spatial_dim(kin_);
  std::map<CellType, std::unique_ptr<FacetValues>> values;
  std::vector<Index> facet_dofs;
  for (const Facet& facet : it->second) {
    // A facet without a known cell is integrated by rank 0 so that it counts exactly once.
    const bool mine = facet.cell >= 0 ? static_cast<bool>(cell_owned_[facet.cell])
                                      : (cell_owned_.empty() || cell_owned_[0]);
    if (!mine) continue;
    auto& fv = values[facet.type];
    if (!fv) fv = std::make_unique<FacetValues>(facet.type, kin_, 2 * cell_order(facet.type) + 1);
    fv->reinit(mesh_, facet);
    dofs_.node_dofs(facet.nodes.data(), static_cast<int>(facet.nodes.size()), facet_dofs);
    for (int q = 0; q < fv->num_points(); ++q) {
      double t[3] = {0, 0, 0};
      for (int i = 0; i < dim; ++i)
        t[i] = is_pressure ? -pressure * fv->normal(q)[i] : traction[i];
      for (int a = 0; a < fv->num_nodes(); ++a)
        for (int i = 0; i < dim; ++i)
          f.add(facet_dofs[a * dim + i], fv->shape(q, a) * t[i] * fv->JxW(q));
    }
  }
}

void LoadAssembler::add_gravity(const std::vector<const Material*>& material_of_region,
                                DistributedVector& f) const {
  const int dim = spatial_dim(kin_);
  const int vertical = dim - 1;
  std::map<CellType, std::unique_ptr<ElementValues>> values;
  std::vector<Index> cell_dofs;
  for (Index c = 0; c < mesh_.num_cells(); ++c) {
    if (!cell_owned_[c]) continue;
    const Material* mat = material_of_region[mesh_.cell_regions[c]];
    const double gamma = mat ? mat->unit_weight() : 0.0;
    if (gamma == 0.0) continue;
    auto& ev = values[mesh_.cell_types[c]];
    if (!ev)
      ev = std::make_unique<ElementValues>(mesh_.cell_types[c], kin_,
                                           2 * cell_order(mesh_.cell_types[c]) + 1);
    ev->reinit(mesh_, c);
    dofs_.cell_dofs(mesh_, c, cell_dofs);
    for (int q = 0; q < ev->num_points(); ++q)
      for (int a = 0; a < ev->num_nodes(); ++a)
        f.add(cell_dofs[a * dim + vertical], -gamma * ev->shape(q, a) * ev->JxW(q));
  }
}

} // namespace bipot
