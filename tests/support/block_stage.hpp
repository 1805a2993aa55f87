#pragma once
/// Test helpers: the block-on-base models (regions base and block of a blocks mesh with sets
/// bottom and top) as YAML text: their mesh and a stage.

#include <string>

namespace bipot::test {

/// The `mesh:` section: a 1 m wide base (y in [-0.5, 0]) under a block (y in [0, 0.5]),
/// 4 quad4 cells across, 2 in the base's height and 3 in the block's.
inline const std::string block_on_base_mesh = "mesh:\n  blocks:\n    cell: quad4\n"
                                              "    x: {breaks: [0, 1.0], cells: [4]}\n"
                                              "    y: {breaks: [-0.5, 0, 0.5], cells: [2, 3]}\n"
                                              "    regions: [base, block]\n";

/// Up to `stages:`, the block on an elastic base (E = 1e5 kPa, ν = 0.3) joined by an RCCM joint
/// (C_n = C_t = 1e6 kN/m³, w = 1e-4 kJ/m², μ = 0.3, α = 0.01 kN·s/m), solved by a direct
/// solver: `block` is the block's material and `contact_solver` the contact solver's keys,
/// both YAML flow maps.
inline std::string block_on_rccm_joint(const std::string& block,
                                       const std::string& contact_solver) {
  return std::string("kinematics: plane_strain\n") + block_on_base_mesh +
         "materials:\n"
         "  base: {type: linear_elastic, youngs_modulus: 1.0e5, poissons_ratio: 0.3}\n"
         "  block: " +
         block +
         "\nlinear_solver: {method: direct}\n"
         "interfaces:\n  - name: joint\n    between: [base, block]\n    law: rccm\n"
         "    parameters: {normal_stiffness: 1.0e6, tangential_stiffness: 1.0e6, "
         "decohesion_energy: 1.0e-4, friction_coefficient: 0.3, adhesion_viscosity: 0.01}\n"
         "contact_solver: " +
         contact_solver + "\nstages:\n";
}

/// The stage `name` with the bottom fixed and the top moved to (x, y) (m) at its end over
/// `increments`; `extra` (indented YAML lines) is inserted before its conditions.
inline std::string block_stage(const std::string& name, double x, double y,
                               const std::string& extra = "", int increments = 3) {
  return "  - name: " + name + "\n    increments: " + std::to_string(increments) + "\n" + extra +
         "    boundary_conditions:\n"
         "      - {set: bottom, component: x, value: 0}\n"
         "      - {set: bottom, component: y, value: 0}\n"
         "      - {set: top, component: x, value: " +
         std::to_string(x) + "}\n      - {set: top, component: y, value: " + std::to_string(y) +
         "}\n";
}

} // namespace bipot::test
