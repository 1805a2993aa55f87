#pragma once
/// Reads and validates a bipot input file in one pass.

#include "fem/input/problem_spec.hpp"

#include <string>

namespace bipot {

/// Parses `path`, checks every key, type and range it can without the mesh, and returns the
/// problem. Throws InputError listing every problem as "file:line:col: key.path: message";
/// a YAML syntax error is reported with its line and column.
ProblemSpec read_problem_file(const std::string& path);

/// Same from text (tests); `file_name` is used in messages, and relative mesh paths are
/// resolved against the current directory.
ProblemSpec read_problem_text(const std::string& text, const std::string& file_name);

/// The top-level keys and a one-line doc for each, for `bipot describe input` and the docs.
std::string describe_input_format();

} // namespace bipot
