// The docs' parameter tables are the schemas' own output: they cannot drift from the code.
#include "contact/solver/contact_solver_options.hpp"
#include "fem/input/stage_schema.hpp"
#include "fem/linalg/linear_solver.hpp"
#include "materials/material_registry.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace bipot {
namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(DocsTablesMatchSchemas, InputReference) {
  const std::string doc = read(BIPOT_SOURCE_DIR "/docs/input_reference.md");
  ASSERT_FALSE(doc.empty());
  for (const auto& name : builtin_materials().names()) {
    EXPECT_NE(doc.find("### `" + name + "`"), std::string::npos) << name;
    EXPECT_NE(doc.find(builtin_materials().schema(name).markdown_table()), std::string::npos)
        << "docs/input_reference.md: paste `bipot describe --markdown " << name << "`";
  }
  EXPECT_NE(doc.find(LinearSolver::schema().markdown_table()), std::string::npos)
      << "docs/input_reference.md: paste `bipot describe --markdown linear_solver`";
  for (const auto& name : contact::contact_solvers().names()) {
    EXPECT_NE(doc.find("### `" + name + "`"), std::string::npos) << name;
    EXPECT_NE(doc.find(contact::contact_solvers().schema(name).markdown_table()), std::string::npos)
        << "docs/input_reference.md: paste `bipot describe --markdown " << name << "`";
  }
}

TEST(DocsTablesMatchSchemas, InputStages) {
  const std::string doc = read(BIPOT_SOURCE_DIR "/docs/input_stages.md");
  ASSERT_FALSE(doc.empty());
  EXPECT_NE(doc.find(stage_schema().markdown_table()), std::string::npos)
      << "docs/input_stages.md: paste `bipot describe --markdown stage`";
  EXPECT_NE(doc.find(control_schema().markdown_table()), std::string::npos)
      << "docs/input_stages.md: paste `bipot describe --markdown control`";
}

} // namespace
} // namespace bipot
