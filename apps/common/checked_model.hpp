#pragma once
/// The model every app solves: built, then checked for what a solve would not survive or
/// would get silently wrong — by `check` and before `run` solves anything.

#include "fem/analysis/model.hpp"
#include "fem/input/problem_spec.hpp"

namespace bipot::app {

/// build_model(spec), then every check that needs the built model: conditions fixing a shared
/// node differently (conflicting_conditions), the mesh (mesh_problems: non-finite
/// coordinates, inverted cells, coincident nodes no interface pairs, nodes of no cell) and,
/// once the mesh is sound, bodies free to move rigidly in some stage (free_rigid_body_modes).
/// Throws InputError listing every problem found.
Model checked_model(const ProblemSpec& spec);

} // namespace bipot::app
