#pragma once
// Helpers of the input tests: the problems an input text produces, and text edits.
#include "fem/analysis/model.hpp"
#include "fem/core/error.hpp"
#include "fem/input/problem_reader.hpp"
#include "tests/support/model_from_text.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace bipot {

/// The problems reported while reading `text` and building its model (none if it is valid).
inline std::vector<std::string> problems_of(const std::string& text) {
  try {
    bipot::test::model_from_text(text, "in.yaml");
  } catch (const InputError& e) {
    return e.problems();
  }
  return {};
}

/// Lines 1-10 of an input: two unit squares side by side, regions `left` and `right`, both
/// linear elastic.
inline std::string two_regions_text() {
  return "kinematics: plane_strain\n"                                                     // 1
         "mesh:\n  blocks:\n    cell: quad4\n"                                            // 2-4
         "    x: {breaks: [0, 1, 2], cells: [1, 1]}\n"                                    // 5
         "    y: {breaks: [0, 1], cells: [1]}\n"                                          // 6
         "    regions: [left, right]\n"                                                   // 7
         "materials:\n"                                                                   // 8
         "  left: {type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.3}\n"   // 9
         "  right: {type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.3}\n"; // 10
}

/// `text` with the first `from` replaced by `to` (which must be there).
inline std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return text.replace(pos, from.size(), to);
}

/// Whether one of `problems` contains `s`.
inline ::testing::AssertionResult has(const std::vector<std::string>& problems,
                                      const std::string& s) {
  for (const auto& p : problems)
    if (p.find(s) != std::string::npos) return ::testing::AssertionSuccess();
  std::string all;
  for (const auto& p : problems)
    all += "\n  " + p;
  return ::testing::AssertionFailure() << "no problem contains \"" << s << "\" in:" << all;
}

/// Whether `text` with the first `from` replaced by `to` reports a problem containing
/// `expected`.
inline ::testing::AssertionResult reports(const std::string& text, const std::string& from,
                                          const std::string& to, const std::string& expected) {
  return has(problems_of(replace(text, from, to)), expected);
}

} // namespace bipot
