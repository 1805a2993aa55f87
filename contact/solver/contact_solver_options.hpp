#pragma once
/// How interfaces are enforced (the *solver*), chosen in YAML apart from the *law*.
///
/// Both solvers iterate the bipotential fixed point r = Proj_{K_μ̄}(r − ρ[Δg_t + (g_n +
/// μ̄‖Δg_t‖) n]) of docs/formulation.md §4 together with bulk equilibrium. Inside each bulk solve
/// the interface force t(u; r̂) = Proj(r̂ − ρ G(u)) − β(u)² C g(u) is linearised in u with
/// the projection's generalized Jacobian (a semi-smooth Newton step at fixed multiplier r̂).
/// - bipotential_uzawa (the seed's algorithm): r̂ is frozen until equilibrium is reached,
///   then updated by the predictor–corrector r̂ ← Proj(τ); repeated until r̂ stops changing.
///   The matrix is rebuilt and refactored only when the interface tangent changed.
/// - semismooth_newton (inexact augmented Lagrangian): r̂ ← Proj(τ) as soon as the residual
///   of the current inner problem dropped tenfold, so equilibrium and the contact law
///   converge together. (Moving r̂ after every iteration, Alart–Curnier style with the
///   multiplier condensed, cycled between stick and slip on the sheared-block test.)
/// - generalized_newton: the multipliers are unknowns of the Newton step itself, with the
///   exact generalized Jacobian of the fixed point (interface_newton_system.hpp); no outer
///   multiplier loop.

#include "fem/core/nonlinear_solver_options.hpp"
#include "fem/core/parameter_binding.hpp"
#include "fem/core/registry.hpp"

#include <string>
#include <vector>

namespace bipot::contact {

/// The driver's part (type, tolerance, limits) and the augmentation of the projection.
struct ContactSolverOptions : NonlinearSolverOptions {
  double augmentation = 0;         ///< ρ (kN/m³); 0 = automatic per pair
  double augmentation_factor = 30; ///< multiplies the automatic ρ
};

/// Each solver's keys bound to the members of ContactSolverOptions (the registry's schemas;
/// a key a solver lacks leaves the struct's value).
std::vector<ParamSchemaOf<ContactSolverOptions>> contact_solver_schemas();

/// The solvers by YAML name, each with its parameter schema (for validation and docs).
/// Registry entries build a ContactSolverOptions from validated parameters.
const Registry<ContactSolverOptions>& contact_solvers();

/// Options of the default solver (generalized_newton with its defaults).
ContactSolverOptions default_contact_solver();

} // namespace bipot::contact
