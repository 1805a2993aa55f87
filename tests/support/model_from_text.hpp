#pragma once
// The model of an input text, read and built with bipot's built-in catalogue: what most
// verification tests start from.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "fem/analysis/model.hpp"
#include "fem/input/problem_reader.hpp"

#include <string>

namespace bipot::test {

inline Model model_from_text(const std::string& text, const std::string& file_name,
                             const Catalogue& catalogue = builtin_catalogue()) {
  return build_model(read_problem_text(text, file_name, catalogue), catalogue);
}

} // namespace bipot::test
