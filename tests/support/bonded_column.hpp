#pragma once
/// The column of the snap-back tests: elastic (height L, modulus E, ν = 0) on a base, bonded
/// by a quasi-static RCCM interface (α = 0, no friction) and pulled at its top by δ = 0.12 λ.
/// With ν = 0 it is 1D: the interface stress t(g) equals the column stress k(δ − g), k = E/L,
///   t(g) = C g for g ≤ g* = √(w/C),  t(g) = w²/(C g³) beyond (β = w/(C g²)).
/// The softening slope at g*, 3C, is 30 k: past the peak (δ* = g* + √(wC)/k = 0.11 m) the
/// equilibrium curve δ(g) = g + t(g)/k snaps back.

#include <cmath>
#include <string>

namespace bipot::test::column {

constexpr double C = 1.0e4, w = 1.0, E = 1.0e3, L = 1.0, k = E / L, width = 0.1, top = 0.12;
inline const double g_star = std::sqrt(w / C);
inline const double peak = std::sqrt(w * C);
inline const double delta_star = g_star + peak / k;

/// Interface stress on the branch the loading follows (β only decreases), for opening g.
inline double t_of(double g) {
  return g <= g_star ? C * g : w * w / (C * g * g * g);
}

/// The column's input: 12 increments, `solver` the contact solver, `control` the stage's
/// control (empty: the default ramp).
inline std::string input(const std::string& solver, const std::string& control = "") {
  return "kinematics: plane_strain\n"
         "mesh:\n  blocks:\n    cell: quad4\n"
         "    x: {breaks: [0, 0.1], cells: [1]}\n"
         "    y: {breaks: [-0.1, 0, 1.0], cells: [1, 2]}\n"
         "    regions: [base, column]\n"
         "  sets:\n    base_nodes: {min: [0, -0.1], max: [0.1, 0], region: base}\n"
         "materials:\n"
         "  base: {type: linear_elastic, youngs_modulus: 1.0e3, poissons_ratio: 0.0}\n"
         "  column: {type: linear_elastic, youngs_modulus: 1.0e3, poissons_ratio: 0.0}\n"
         "linear_solver: {method: direct}\n"
         "interfaces:\n  - name: bond\n    between: [base, column]\n    law: rccm\n"
         "    parameters: {normal_stiffness: 1.0e4, tangential_stiffness: 1.0e4, "
         "decohesion_energy: 1.0, friction_coefficient: 0.0}\n"
         "contact_solver: {type: " +
         solver +
         ", tolerance: 1.0e-10, max_cutbacks: 3}\n"
         "stages:\n  - name: pull\n    increments: 12\n" +
         (control.empty() ? std::string() : "    control: " + control + "\n") +
         "    boundary_conditions:\n"
         "      - {set: base_nodes, component: x, value: 0}\n"
         "      - {set: base_nodes, component: y, value: 0}\n"
         "      - {set: top, component: x, value: 0}\n"
         "      - {set: top, component: y, value: 0.12}\n";
}

} // namespace bipot::test::column
