#pragma once
/// "Did you mean ...?" suggestions for unknown keys and names.

#include <string>
#include <vector>

namespace bipot {

/// Edit (Levenshtein) distance between two strings.
int edit_distance(const std::string& a, const std::string& b);

/// The candidate closest to `name`, or "" when none is within a plausible distance
/// (at most a third of the longer length, at least 2 edits allowed).
std::string nearest_name(const std::string& name, const std::vector<std::string>& candidates);

/// "a, b, c" — used in messages listing the allowed keys or registered names.
std::string join_names(const std::vector<std::string>& names, const std::string& sep = ", ");

/// "no <kind> named '<name>' in the mesh (did you mean '<nearest>'?); available: <known>".
std::string unknown_in_mesh(const std::string& kind, const std::string& name,
                            const std::vector<std::string>& known);

} // namespace bipot
