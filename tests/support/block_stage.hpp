#pragma once
/// Test helper: a stage of the block-on-base models (regions base and block of a blocks
/// mesh with sets bottom and top) as YAML text.

#include <string>

namespace bipot::test {

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
