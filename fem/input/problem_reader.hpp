#pragma once
/// Reads and validates a bipot input file in one pass.

#include "fem/input/input_catalogue.hpp"
#include "fem/input/problem_spec.hpp"

#include <string>

namespace bipot {

/// Limits that refuse an absurd input at `check` with a clear message, before it exhausts
/// memory or time (docs/input_reference.md, "Limits").
constexpr int max_increments_per_stage = 1000000;
/// Cells of a `blocks` mesh, counted after quads are split into triangles (2 each) and
/// hexahedra into tetrahedra (6 each).
constexpr long max_block_mesh_cells = 200000000;

/// Parses `path`, checks every key, type and range it can without the mesh, and returns the
/// problem. Throws InputError listing every problem as "file:line:col: key.path: message";
/// a YAML syntax error is reported with its line and column. Materials, laws and contact
/// solvers are looked up in `catalogue` (an application's Catalogue converts to it).
ProblemSpec read_problem_file(const std::string& path, const InputCatalogue& catalogue);

/// Same from text (tests); `file_name` is used in messages, and relative mesh paths are
/// resolved against the current directory.
ProblemSpec read_problem_text(const std::string& text, const std::string& file_name,
                              const InputCatalogue& catalogue);

/// The rules of path-following stages that need the rest of the problem (contact solver,
/// interfaces, the previous stage), for a ProblemSpec built by an app rather than read from
/// a bipot file (read_problem_* apply them already), and those of output.checkpoint (stage
/// names, steps in range). Throws InputError naming each stage.
void check_stage_controls(const ProblemSpec& spec);

/// The top-level keys and a one-line doc for each, for `bipot describe input` and the docs.
std::string describe_input_format();

} // namespace bipot
