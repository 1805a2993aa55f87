#pragma once
/// External loads: pressure and traction on facet sets, gravity from material unit weights.
/// Each rank integrates the facets whose adjacent cell it owns and its own cells.

#include "fem/assembly/dof_map.hpp"
#include "fem/core/material.hpp"
#include "fem/element/kinematics.hpp"
#include "fem/mesh/mesh.hpp"

#include <array>
#include <vector>

namespace bipot {

class DistributedVector;

class LoadAssembler {
public:
  /// `cell_owned[c]` tells whether this rank owns cell c (facets follow their cell).
  LoadAssembler(const Mesh& mesh, Kinematics kin, const DofMap& dofs, std::vector<bool> cell_owned);

  /// Adds ∫ N (−p n) dΓ: `pressure` (kPa) acts against the outward normal of the facets.
  void add_pressure(const std::string& facet_set, double pressure, DistributedVector& f) const;
  /// Adds ∫ N t dΓ for a constant traction vector (kPa, spatial components).
  void add_traction(const std::string& facet_set, const std::vector<double>& traction,
                    DistributedVector& f) const;
  /// Adds ∫ N b dV with b = −γ e_vertical (vertical: y in 2D / axisymmetric, z in 3D).
  void add_gravity(const std::vector<const Material*>& material_of_region,
                   DistributedVector& f) const;

private:
  void add_facet_load(const std::string& facet_set, DistributedVector& f, bool is_pressure,
                      double pressure, const std::vector<double>& traction) const;
  const Mesh& mesh_;
  Kinematics kin_;
  const DofMap& dofs_;
  std::vector<bool> cell_owned_;
};

} // namespace bipot
