#pragma once
/// The model every app solves: built, then checked for what a solve would not survive or
/// would get silently wrong — by `check` and before `run` solves anything.

#include "apps/catalogue/catalogue.hpp"
#include "fem/analysis/model.hpp"
#include "fem/input/problem_spec.hpp"

namespace bipot::app {

/// build_model(spec, catalogue), then every check that needs the built model: conditions fixing a
/// shared node differently (conflicting_conditions), the mesh (mesh_problems: non-finite
/// coordinates, inverted cells, coincident nodes no interface pairs, nodes of no cell) and,
/// once the mesh is sound, bodies free to move rigidly in some stage (free_rigid_body_modes).
/// Throws InputError listing every problem found.
Model checked_model(const ProblemSpec& spec, const Catalogue& catalogue);

/// What `check` verifies: checked_model(spec) and that the results could be written into
/// spec.output.directory (results_folder_problem, the check a run makes before solving,
/// reported at output.directory). Throws InputError listing every problem of both.
Model checked_model_and_results_folder(const ProblemSpec& spec, const Catalogue& catalogue);

/// What a run survives but is probably not what was meant (large_increment_warnings: a
/// prescribed step larger than the model), printed by `check` and by `run` before it solves:
/// on rank 0, to stderr, one line each, "<program>: warning: file:line:col: key.path: ...".
void print_model_warnings(const Model& model, const std::string& program);

} // namespace bipot::app
